#include "tensor/eigen.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace tg::tensor {
namespace {

constexpr int kMaxSweeps = 32;

// One Jacobi rotation zeroing a[p][q]; accumulates into v (columns = vectors).
void rotate(double a[3][3], double v[3][3], int p, int q) {
  const double apq = a[p][q];
  if (apq == 0.0) return;
  const double theta = (a[q][q] - a[p][p]) / (2.0 * apq);
  // Smaller root of t^2 + 2 theta t - 1 = 0, written to avoid overflow of theta^2.
  const double t = std::abs(theta) > 1e150
                       ? 0.5 / theta
                       : std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
  const double c = 1.0 / std::sqrt(t * t + 1.0);
  const double s = t * c;
  const double tau = s / (1.0 + c);
  a[p][p] -= t * apq;
  a[q][q] += t * apq;
  a[p][q] = a[q][p] = 0.0;
  const int r = 3 - p - q;
  const double arp = a[r][p], arq = a[r][q];
  a[r][p] = a[p][r] = arp - s * (arq + tau * arp);
  a[r][q] = a[q][r] = arq + s * (arp - tau * arq);
  for (int k = 0; k < 3; ++k) {
    const double vkp = v[k][p], vkq = v[k][q];
    v[k][p] = vkp - s * (vkq + tau * vkp);
    v[k][q] = vkq + s * (vkp - tau * vkq);
  }
}

// The eigenvector of a (scaled, symmetric) for the simple eigenvalue l: the
// largest cross product of two rows of a - l I, which is orthogonal to both.
// Returns false when every cross product is tiny (l not simple enough).
bool simpleVector(const double a[3][3], double l, glm::dvec3& v) {
  const glm::dvec3 r0(a[0][0] - l, a[0][1], a[0][2]), r1(a[1][0], a[1][1] - l, a[1][2]),
      r2(a[2][0], a[2][1], a[2][2] - l);
  const glm::dvec3 c[3] = {glm::cross(r0, r1), glm::cross(r0, r2), glm::cross(r1, r2)};
  int best = 0;
  double n2[3];
  for (int k = 0; k < 3; ++k) n2[k] = glm::dot(c[k], c[k]);
  if (n2[1] > n2[best]) best = 1;
  if (n2[2] > n2[best]) best = 2;
  if (!(n2[best] > 1e-20)) return false;
  v = c[best] / std::sqrt(n2[best]);
  return true;
}

// Closed form (Smith 1961, "Eigenvalues of a symmetric 3x3 matrix", CACM
// 4(4)): eigenvalues from the trigonometric solution of the characteristic
// cubic of the deviator, eigenvectors of the two outer ones by cross products
// (as Kopp's hybrid method, arXiv:physics/0610206). Used only when both
// eigenvalue gaps exceed 1e-3 of the deviator's norm, where the vectors are
// accurate to ~1e-13; otherwise returns false and Jacobi takes over.
bool analytic(const double a[3][3], Eigensystem& out) {
  const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
  const double b00 = a[0][0] - q, b11 = a[1][1] - q, b22 = a[2][2] - q;
  const double p2 = (b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * (a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2])) / 6.0;
  if (!(p2 > 1e-12)) return false;
  const double p = std::sqrt(p2);
  const double det = b00 * (b11 * b22 - a[1][2] * a[1][2]) - a[0][1] * (a[0][1] * b22 - a[1][2] * a[0][2]) +
                     a[0][2] * (a[0][1] * a[1][2] - b11 * a[0][2]);
  const double r = std::clamp(det / (2.0 * p2 * p), -1.0, 1.0);
  const double phi = std::acos(r) / 3.0;
  const double c = std::cos(phi), s = std::sin(phi);  // one sincos
  const double l1 = q + 2.0 * p * c;
  const double l3 = q + 2.0 * p * (-0.5 * c - 0.8660254037844386 * s);  // cos(phi + 2 pi / 3)
  const double l2 = 3.0 * q - l1 - l3;
  if (std::min(l1 - l2, l2 - l3) < 1e-3 * p) return false;
  // An eigenvalue near zero comes out of the cubic with an absolute error of
  // ~1e-16 of the largest: enough to flip its sign, and the sign picks the
  // glyph's shape family. Jacobi resolves such tensors exactly.
  if (std::min({std::abs(l1), std::abs(l2), std::abs(l3)}) < 1e-9 * std::max(std::abs(l1), std::abs(l3))) return false;
  glm::dvec3 v1, v3;
  if (!simpleVector(a, l1, v1) || !simpleVector(a, l3, v3)) return false;
  v3 = glm::normalize(v3 - glm::dot(v3, v1) * v1);
  out.values = glm::dvec3(l1, l2, l3);
  out.vectors = {v1, glm::cross(v3, v1), v3};  // right-handed: v1 x v2 = v3
  return true;
}

}  // namespace

Eigensystem eigensolve(const SymTensor& t) {
  Eigensystem out;
  out.vectors = {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
  const double scale = std::max({std::abs(t.xx), std::abs(t.xy), std::abs(t.xz), std::abs(t.yy),
                                 std::abs(t.yz), std::abs(t.zz)});
  if (scale == 0.0) return out;
  const double inv = 1.0 / scale;
  double a[3][3] = {{t.xx * inv, t.xy * inv, t.xz * inv},
                    {t.xy * inv, t.yy * inv, t.yz * inv},
                    {t.xz * inv, t.yz * inv, t.zz * inv}};
  if (a[0][1] == 0.0 && a[0][2] == 0.0 && a[1][2] == 0.0) {
    // Diagonal: exact, and common (isotropic backgrounds, axis-aligned phantoms).
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int i, int j) { return a[i][i] > a[j][j]; });
    for (int i = 0; i < 3; ++i) {
      out.values[i] = a[order[i]][order[i]] * scale;
      out.vectors[i] = glm::dvec3(0.0);
      out.vectors[i][order[i]] = 1.0;
    }
    out.vectors[2] = glm::cross(out.vectors[0], out.vectors[1]);
    return out;
  }
  if (analytic(a, out)) {
    out.values *= scale;
    return out;
  }
  double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    const double off = std::abs(a[0][1]) + std::abs(a[0][2]) + std::abs(a[1][2]);
    if (off == 0.0) break;
    const double diag = std::abs(a[0][0]) + std::abs(a[1][1]) + std::abs(a[2][2]);
    // Entries are O(1) after scaling; below 1e-18 of the norm they no longer
    // change any eigenvalue in double precision.
    if (off < 1e-18 * std::max(diag, 1.0)) break;
    rotate(a, v, 0, 1);
    rotate(a, v, 0, 2);
    rotate(a, v, 1, 2);
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return a[i][i] > a[j][j]; });
  for (int i = 0; i < 3; ++i) {
    out.values[i] = a[order[i]][order[i]] * scale;
    out.vectors[i] = glm::normalize(glm::dvec3(v[0][order[i]], v[1][order[i]], v[2][order[i]]));
  }
  // Right-handed frame, so the frame is a rotation and maps to a quaternion.
  out.vectors[2] = glm::normalize(glm::cross(out.vectors[0], out.vectors[1]));
  return out;
}

}  // namespace tg::tensor
