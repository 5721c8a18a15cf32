// Tier 1: the symmetric eigensolver against Teem's ell_3m_eigensolve_d and
// against its own defining properties, on random and adversarial tensors.
#include <gtest/gtest.h>
#include <teem/ell.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "tensor/eigen.h"

using tg::tensor::eigensolve;
using tg::tensor::Eigensystem;
using tg::tensor::SymTensor;

namespace {

double frob(const SymTensor& t) {
  return std::sqrt(t.xx * t.xx + t.yy * t.yy + t.zz * t.zz + 2 * (t.xy * t.xy + t.xz * t.xz + t.yz * t.yz));
}

glm::dvec3 apply(const SymTensor& t, const glm::dvec3& v) {
  return {t.xx * v.x + t.xy * v.y + t.xz * v.z, t.xy * v.x + t.yy * v.y + t.yz * v.z,
          t.xz * v.x + t.yz * v.y + t.zz * v.z};
}

// Residual |T v - l v| <= tol |T|, orthonormal right-handed frame, descending values.
void expectValid(const SymTensor& t, const Eigensystem& es, double tol = 1e-12) {
  const double n = frob(t);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(std::isfinite(es.values[i]));
    const glm::dvec3 r = apply(t, es.vectors[i]) - es.values[i] * es.vectors[i];
    EXPECT_LE(glm::length(r), tol * std::max(n, 1e-300)) << "vector " << i;
    EXPECT_NEAR(glm::length(es.vectors[i]), 1.0, 1e-14);
  }
  EXPECT_NEAR(glm::dot(es.vectors[0], es.vectors[1]), 0.0, 1e-13);
  EXPECT_NEAR(glm::dot(es.vectors[0], es.vectors[2]), 0.0, 1e-13);
  EXPECT_NEAR(glm::dot(glm::cross(es.vectors[0], es.vectors[1]), es.vectors[2]), 1.0, 1e-13);
  EXPECT_GE(es.values[0], es.values[1]);
  EXPECT_GE(es.values[1], es.values[2]);
}

SymTensor fromEigen(const glm::dvec3& l, double a, double b, double c) {
  // R = Rz(a) Ry(b) Rx(c)
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b), cc = std::cos(c), sc = std::sin(c);
  const double r[3][3] = {{ca * cb, ca * sb * sc - sa * cc, ca * sb * cc + sa * sc},
                          {sa * cb, sa * sb * sc + ca * cc, sa * sb * cc - ca * sc},
                          {-sb, cb * sc, cb * cc}};
  auto m = [&](int i, int j) { return r[i][0] * l.x * r[j][0] + r[i][1] * l.y * r[j][1] + r[i][2] * l.z * r[j][2]; };
  return {m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)};
}

}  // namespace

TEST(Eigen, RandomTensorsMatchTeem) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 20000; ++k) {
    const SymTensor t{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
    const Eigensystem es = eigensolve(t);
    expectValid(t, es);
    const double m[9] = {t.xx, t.xy, t.xz, t.xy, t.yy, t.yz, t.xz, t.yz, t.zz};
    double ev[3], evec[9];
    ell_3m_eigensolve_d(ev, evec, m, AIR_TRUE);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(es.values[i], ev[i], 1e-10) << "tensor " << k;
  }
}

TEST(Eigen, ZeroTensorGivesZeroValuesAndIdentity) {
  const Eigensystem es = eigensolve({});
  for (int i = 0; i < 3; ++i) EXPECT_EQ(es.values[i], 0.0);
  expectValid({}, es);
}

TEST(Eigen, RepeatedEigenvaluesAreExact) {
  for (double l : {1.0, -3.0, 1e-30, 1e30}) {
    const SymTensor iso{l, 0, 0, l, 0, l};
    const Eigensystem es = eigensolve(iso);
    for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(es.values[i], l);  // scaling by |T| costs <= 1 ulp
    expectValid(iso, es);
    // Rotated with a double eigenvalue: the odd one out and its vector exact.
    const SymTensor t = fromEigen({2 * l, l, l}, 0.3, 1.1, -0.7);
    const Eigensystem e2 = eigensolve(t);
    expectValid(t, e2, 1e-13);
    if (l > 0) {
      EXPECT_NEAR(e2.values[0] / l, 2.0, 1e-13);
      EXPECT_NEAR(e2.values[1] / l, 1.0, 1e-13);
    }
  }
}

TEST(Eigen, AdversarialScalesAndSigns) {
  const glm::dvec3 cases[] = {{1, 1e-6, 1e-6}, {1, 1, 1e-6},   {1, 0, 0},     {1, -1, 0},
                              {-1, -2, -3},    {1e-300, 0, 0}, {1e300, 1, 0}, {5, 5, 5 + 1e-12}};
  for (const auto& l : cases)
    for (double a : {0.0, 0.4, 2.0}) {
      const SymTensor t = fromEigen(l, a, 0.7 * a, -0.5);
      const Eigensystem es = eigensolve(t);
      expectValid(t, es, 1e-12);
      double sorted[3] = {l.x, l.y, l.z};
      std::sort(sorted, sorted + 3, std::greater<>());
      const double scale = std::max({std::abs(l.x), std::abs(l.y), std::abs(l.z)});
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(es.values[i], sorted[i], 1e-12 * scale);
    }
}

TEST(Eigen, DiagonalIsUntouched) {
  const SymTensor t{3, 0, 0, -1, 0, 2};
  const Eigensystem es = eigensolve(t);
  EXPECT_EQ(es.values[0], 3.0);
  EXPECT_EQ(es.values[1], 2.0);
  EXPECT_EQ(es.values[2], -1.0);
  expectValid(t, es);
}

// The lane kernel's root finder across the whole range of r = cos(3φ): the
// middle eigenvalue sweeps from next to the smallest to next to the largest,
// so r runs from -1 to 1 and both branches of the deflation are taken.
TEST(Eigen, ClosedFormAcrossTheCubicsRange) {
  for (int k = 0; k <= 400; ++k) {
    const double mid = -0.99 + 2.98 * k / 400.0;  // in (-1, 2)
    const glm::dvec3 l{2.0, mid, -1.0};
    const SymTensor t = fromEigen(l, 0.3 + k, 0.9, -0.4 * k);
    const Eigensystem es = eigensolve(t);
    expectValid(t, es, 1e-12);
    double sorted[3] = {l.x, l.y, l.z};
    std::sort(sorted, sorted + 3, std::greater<>());
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(es.values[i], sorted[i], 1e-13) << "mid " << mid;
  }
}

// eigensolveBlock must give eigensolve()'s results lane by lane, bit for bit
// (one kernel text, no FMA contraction: CMakeLists.txt), whichever path each
// lane takes (closed form, diagonal, Jacobi), for any count.
TEST(Eigen, BlockAgreesWithScalarOnEveryPath) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<SymTensor> cases;
  for (int k = 0; k < 120; ++k) cases.push_back({u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)});
  cases.push_back({});                                          // zero
  cases.push_back({3, 0, 0, -1, 0, 2});                         // diagonal
  cases.push_back({5, 0, 0, 5, 0, 5});                          // isotropic
  cases.push_back(fromEigen({2, 1, 1}, 0.3, 1.1, -0.7));        // double eigenvalue
  cases.push_back(fromEigen({1, 1e-12, -0.5}, 0.2, 0.4, 0.6));  // near-zero eigenvalue
  cases.push_back(fromEigen({1e-30, 5e-31, 1e-31}, 1, 2, 3));   // tiny
  cases.push_back(fromEigen({1e30, -5e29, 1e29}, 3, 2, 1));     // huge
  for (int k = 0; k < 20; ++k) cases.push_back(cases[std::size_t(k) * 7 % cases.size()]);
  std::vector<float> flat;
  for (const SymTensor& t : cases)
    for (double c : {t.xx, t.xy, t.xz, t.yy, t.yz, t.zz}) flat.push_back(float(c));
  const std::size_t total = cases.size();
  tg::tensor::EigenBlock block;
  for (std::size_t count : {std::size_t(1), std::size_t(3), std::size_t(37), tg::tensor::kEigenBlock}) {
    for (std::size_t b = 0; b < total; b += count) {
      const std::size_t n = std::min(count, total - b);
      tg::tensor::eigensolveBlock(&flat[6 * b], n, block);
      for (std::size_t k = 0; k < n; ++k) {
        const float* f = &flat[6 * (b + k)];
        const Eigensystem es = eigensolve({f[0], f[1], f[2], f[3], f[4], f[5]});
        for (int i = 0; i < 3; ++i) {
          EXPECT_EQ(block.values[i][k], es.values[i]) << "tensor " << b + k;
          for (int c = 0; c < 3; ++c) EXPECT_EQ(block.vectors[i][c][k], es.vectors[i][c]) << "tensor " << b + k;
        }
      }
    }
  }
}
