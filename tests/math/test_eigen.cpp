// Tier 1: the symmetric eigensolver against Teem's ell_3m_eigensolve_d and
// against its own defining properties, on random and adversarial tensors.
#include <gtest/gtest.h>
#include <teem/ell.h>

#include <cmath>
#include <random>

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
