// Tier 1: anisotropy measures on known eigenvalues.
#include <gtest/gtest.h>

#include <cmath>

#include "tensor/anisotropy.h"

using tg::tensor::anisotropy;

TEST(Anisotropy, KnownShapes) {
  const auto line = anisotropy({1, 0, 0});
  EXPECT_NEAR(line.fa, 1.0, 1e-15);
  EXPECT_NEAR(line.cl, 1.0, 1e-15);
  EXPECT_NEAR(line.cp, 0.0, 1e-15);
  const auto plane = anisotropy({1, 1, 0});
  EXPECT_NEAR(plane.fa, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(plane.cp, 1.0, 1e-15);
  const auto sphere = anisotropy({2, 2, 2});
  EXPECT_EQ(sphere.fa, 0.0);
  EXPECT_NEAR(sphere.cs, 1.0, 1e-15);
  EXPECT_NEAR(sphere.md, 2.0, 1e-15);
}

TEST(Anisotropy, WestinMeasuresSumToOne) {
  for (double a : {0.1, 0.5, 0.9})
    for (double b : {0.05, 0.3}) {
      const auto m = anisotropy({1.0, a, a * b});
      EXPECT_NEAR(m.cl + m.cp + m.cs, 1.0, 1e-14);
    }
}

TEST(Anisotropy, DegenerateInputsStayFinite) {
  const auto z = anisotropy({0, 0, 0});
  EXPECT_EQ(z.fa, 0.0);
  EXPECT_EQ(z.cl, 0.0);
  const auto neg = anisotropy({1, 0, -1});  // trace 0: Westin undefined
  EXPECT_TRUE(std::isfinite(neg.fa));
  EXPECT_EQ(neg.cl + neg.cp + neg.cs, 0.0);
  EXPECT_GT(anisotropy({1, -0.5, -0.5}).fa, 1.0);  // indefinite: FA exceeds 1
}
