#include "tensor/eigen.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "tensor/lanes.h"

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

// The eigenvector of the scaled tensor a for the simple eigenvalue l: the
// largest cross product of two rows of a - l I, which is orthogonal to both.
// `ok` turns false where every cross product is tiny (l not simple enough).
template <class T, class M>
[[gnu::always_inline]] inline V3<T> simpleVector(const T a[6], T l, M& ok) {
  const V3<T> r0{a[0] - l, a[1], a[2]}, r1{a[1], a[3] - l, a[4]}, r2{a[2], a[4], a[5] - l};
  const V3<T> c0 = cross(r0, r1), c1 = cross(r0, r2), c2 = cross(r1, r2);
  const T n0 = dot(c0, c0), n1 = dot(c1, c1), n2 = dot(c2, c2);
  const V3<T> c01 = blend(n1 > n0, c1, c0);
  const T n01 = lmax(n0, n1);
  const V3<T> c = blend(n2 > n01, c2, c01);
  const T n = lmax(n01, n2);
  const T tiny = splat<T>(1e-20);
  ok = ok && n > tiny;
  return mul(c, splat<T>(1.0) / lsqrt(n > tiny ? n : splat<T>(1.0)));
}

// Closed form (Smith 1961, "Eigenvalues of a symmetric 3x3 matrix", CACM
// 4(4)), on a = the tensor scaled by its largest entry (xx xy xz yy yz zz).
// With q = tr(a)/3, p² = |a - qI|²/6 and r = det(a - qI)/(2p³), the
// eigenvalues are q + p·x for the three roots x of x³ - 3x - 2r = 0. Smith
// takes x = 2cos(acos(r)/3 + 2πk/3); we take the root of largest magnitude,
// which is simple for every r (|x| in [√3, 2]), by Newton from a quadratic
// fit, and deflate to a quadratic for the other two: no acos or sincos, so
// that the kernel runs on SIMD lanes (lanes.h). Eigenvectors of the two
// outer eigenvalues by cross products (as Kopp's hybrid method,
// arXiv:physics/0610206). The mask is false where Jacobi must take over: a
// gap below 1e-3 of p (the cross products lose accuracy), p tiny, or an
// eigenvalue within 1e-9 of the largest of zero (the cubic's absolute error
// could flip its sign, and the sign picks the glyph's shape family).
// Elsewhere the vectors are accurate to ~1e-13.
template <class T>
[[gnu::always_inline]] inline auto analytic(const T a[6], T l[3], V3<T> v[3]) {
  const T q = (a[0] + a[3] + a[5]) * (1.0 / 3.0);
  const T b00 = a[0] - q, b11 = a[3] - q, b22 = a[5] - q;
  const T p2 = (b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * (a[1] * a[1] + a[2] * a[2] + a[4] * a[4])) * (1.0 / 6.0);
  auto ok = p2 > splat<T>(1e-12);
  const T p = lsqrt(ok ? p2 : splat<T>(1.0));
  const T det = b00 * (b11 * b22 - a[4] * a[4]) - a[1] * (a[1] * b22 - a[4] * a[2]) +
                a[2] * (a[1] * a[4] - b11 * a[2]);
  const T r = lmin(splat<T>(1.0), lmax(splat<T>(-1.0), det / (2.0 * p * p * p)));
  // y: the largest root of y³ - 3y - 2|r| = 0, in [√3, 2]. The quadratic
  // through |r| = 0, 1/2, 1 is within 2e-3; Newton's constant f''/2f' is
  // below 0.9 there, so four steps reach rounding.
  const T ar = labs(r);
  T y = 1.7320508075688772 + ar * (0.3213884 - 0.0534392 * ar);
  for (int it = 0; it < 4; ++it) y -= (y * (y * y - 3.0) - 2.0 * ar) / (3.0 * (y * y - 1.0));
  // The other two roots: x² - y x + y² - 3 = 0 (for r ≥ 0, sign-flipped for
  // r < 0); 3(2 - y)(2 + y) keeps their gap exact as y nears 2.
  const T d = lsqrt(lmax(splat<T>(0.0), 3.0 * (2.0 - y) * (2.0 + y)));
  const auto pos = r >= splat<T>(0.0);
  const T x1 = pos ? y : 0.5 * (y + d);
  const T x2 = pos ? 0.5 * (d - y) : 0.5 * (y - d);
  const T x3 = pos ? -0.5 * (y + d) : -y;
  ok = ok && lmin(x1 - x2, x2 - x3) >= splat<T>(1e-3);
  l[0] = q + p * x1;
  l[1] = q + p * x2;
  l[2] = q + p * x3;
  const T smallest = lmin(labs(l[1]), lmin(labs(l[0]), labs(l[2])));
  ok = ok && smallest >= 1e-9 * lmax(labs(l[0]), labs(l[2]));
  v[0] = simpleVector(a, l[0], ok);
  const V3<T> w3 = simpleVector(a, l[2], ok);
  const V3<T> o3{w3.x - dot(w3, v[0]) * v[0].x, w3.y - dot(w3, v[0]) * v[0].y, w3.z - dot(w3, v[0]) * v[0].z};
  v[2] = mul(o3, splat<T>(1.0) / lsqrt(dot(o3, o3)));
  v[1] = cross(v[2], v[0]);  // right-handed: v1 x v2 = v3
  return ok;
}

// The six components divided by the largest magnitude, so that tiny (1e-30)
// and huge (1e30) tensors stay out of under/overflow. Returns that magnitude.
template <class T>
[[gnu::always_inline]] inline T scaled(const T t[6], T a[6]) {
  T m = splat<T>(0.0);
  for (int k = 0; k < 6; ++k) m = lmax(m, labs(t[k]));
  const T inv = 1.0 / (m > 0.0 ? m : splat<T>(1.0));
  for (int k = 0; k < 6; ++k) a[k] = t[k] * inv;
  return m;
}

// Off-diagonal entries all zero: such tensors take the exact diagonal path.
template <class T>
[[gnu::always_inline]] inline auto isDiagonal(const T a[6]) {
  return a[1] == 0.0 && a[2] == 0.0 && a[4] == 0.0;
}

// Cyclic Jacobi on the scaled tensor, for what the closed form declines.
Eigensystem jacobi(const double s[6], double scale) {
  double a[3][3] = {{s[0], s[1], s[2]}, {s[1], s[3], s[4]}, {s[2], s[4], s[5]}};
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
  Eigensystem out;
  for (int i = 0; i < 3; ++i) {
    out.values[i] = a[order[i]][order[i]] * scale;
    out.vectors[i] = glm::normalize(glm::dvec3(v[0][order[i]], v[1][order[i]], v[2][order[i]]));
  }
  // Right-handed frame, so the frame is a rotation and maps to a quaternion.
  out.vectors[2] = glm::normalize(glm::cross(out.vectors[0], out.vectors[1]));
  return out;
}

// Diagonal tensors: exact, and common (isotropic backgrounds, axis-aligned
// phantoms, the zero tensor).
Eigensystem diagonal(const double a[6], double scale) {
  const double d[3] = {a[0], a[3], a[5]};
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return d[i] > d[j]; });
  Eigensystem out;
  for (int i = 0; i < 3; ++i) {
    out.values[i] = d[order[i]] * scale;
    out.vectors[i] = glm::dvec3(0.0);
    out.vectors[i][order[i]] = 1.0;
  }
  out.vectors[2] = glm::cross(out.vectors[0], out.vectors[1]);
  return out;
}

// Every path but the closed form: what a block lane falls back to.
Eigensystem slowPath(const double a[6], double scale) { return isDiagonal(a) ? diagonal(a, scale) : jacobi(a, scale); }

}  // namespace

Eigensystem eigensolve(const SymTensor& t) {
  const double in[6] = {t.xx, t.xy, t.xz, t.yy, t.yz, t.zz};
  double a[6];
  const double scale = scaled(in, a);
  double l[3];
  V3<double> v[3];
  if (isDiagonal(a) || !analytic(a, l, v)) return slowPath(a, scale);
  Eigensystem out;
  for (int i = 0; i < 3; ++i) {
    out.values[i] = l[i] * scale;
    out.vectors[i] = glm::dvec3(v[i].x, v[i].y, v[i].z);
  }
  return out;
}

TG_LANE_CLONES void eigensolveBlock(const float* t, std::size_t n, EigenBlock& out) {
  n = std::min(n, kEigenBlock);
  alignas(64) double in[6][kEigenBlock];
  if (n < kEigenBlock)  // lanes >= n are zero: diagonal, no work
    for (auto& c : in) std::fill(c + n, c + kEigenBlock, 0.0);
  for (std::size_t k = 0; k < n; ++k)
    for (int c = 0; c < 6; ++c) in[c][k] = double(t[6 * k + std::size_t(c)]);
  bool ok[kEigenBlock];
  for (std::size_t k = 0; k < kEigenBlock; k += kLanes) {
    Lanes4 tk[6], a[6];
    for (int c = 0; c < 6; ++c) tk[c] = load4(&in[c][k]);
    const Lanes4 m = scaled(tk, a);
    Lanes4 l[3];
    V3<Lanes4> v[3];
    // Diagonal tensors take the exact path, as in eigensolve().
    const auto good = analytic(a, l, v) && !isDiagonal(a);
    for (std::size_t j = 0; j < kLanes; ++j) ok[k + j] = good[j] != 0;
    for (int i = 0; i < 3; ++i) {
      store4(&out.values[i][k], l[i] * m);
      store4(&out.vectors[i][0][k], v[i].x);
      store4(&out.vectors[i][1][k], v[i].y);
      store4(&out.vectors[i][2][k], v[i].z);
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (ok[k]) continue;
    double tk[6], a[6];
    for (int c = 0; c < 6; ++c) tk[c] = in[c][k];
    const double m = scaled(tk, a);
    const Eigensystem es = slowPath(a, m);
    for (int i = 0; i < 3; ++i) {
      out.values[i][k] = es.values[i];
      for (int j = 0; j < 3; ++j) out.vectors[i][j][k] = es.vectors[i][j];
    }
  }
}

}  // namespace tg::tensor
