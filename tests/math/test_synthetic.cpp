// Tier 1: the synthetic fields have the structure they claim.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "data-synthetic/generators.h"
#include "data-synthetic/random_tensors.h"

using namespace tg;

// Boussinesq's stress satisfies equilibrium, div sigma = 0 (no body force),
// and has the closed-form trace -(1 + nu) P z / (pi R^3).
TEST(Boussinesq, EquilibriumAndTrace) {
  const double nu = 0.3, h = 1e-4;
  for (const auto& p : {std::array{0.3, -0.2, 0.5}, std::array{-0.7, 0.4, 0.2}, std::array{0.05, 0.02, 1.0}}) {
    double s[9];
    synth::boussinesqStress(p[0], p[1], p[2], nu, s);
    const double R = std::hypot(p[0], p[1], p[2]);
    EXPECT_NEAR(s[0] + s[4] + s[8], -(1 + nu) * p[2] / (std::numbers::pi * R * R * R), 1e-10);
    double div[3] = {0, 0, 0};
    for (int axis = 0; axis < 3; ++axis) {
      std::array<double, 3> a = p, b = p;
      a[axis] += h;
      b[axis] -= h;
      double sa[9], sb[9];
      synth::boussinesqStress(a[0], a[1], a[2], nu, sa);
      synth::boussinesqStress(b[0], b[1], b[2], nu, sb);
      for (int row = 0; row < 3; ++row) div[row] += (sa[row * 3 + axis] - sb[row * 3 + axis]) / (2 * h);
    }
    const double scale = 1.0 / (R * R * R);  // magnitude of the derivatives
    for (double d : div) EXPECT_LT(std::abs(d), 1e-5 * scale);
  }
}

TEST(Boussinesq, FieldIsIndefinite) {
  const io::TensorField f = synth::boussinesq(8, 0.3);
  EXPECT_EQ(f.size(), 512u);
  EXPECT_EQ(f.skippedNonFinite, 0u);
}

TEST(RandomField, ReproducibleAndPositiveDefinite) {
  synth::RandomTensorStream a(42), b(42), c(43);
  float ta[6], tb[6], tc[6];
  for (int k = 0; k < 1000; ++k) {
    a.next(ta);
    b.next(tb);
    c.next(tc);
    for (int i = 0; i < 6; ++i) ASSERT_EQ(ta[i], tb[i]);
    // Positive definite: leading minors positive.
    EXPECT_GT(ta[0], 0.0f);
    EXPECT_GT(ta[0] * ta[3] - ta[1] * ta[1], 0.0f);
  }
  EXPECT_NE(ta[0], tc[0]);
  const auto d = synth::gridDims(100000000);
  EXPECT_EQ(d.x * d.y * d.z, 100000000u);
  EXPECT_EQ(d.x, 400u);
}
