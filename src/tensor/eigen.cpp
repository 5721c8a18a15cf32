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
