// Tier 1: the superquadric shape mapping, its implicit function and the
// reference root finder, against Teem where Teem has the same formula.
#include <gtest/gtest.h>
#include <teem/ell.h>
#include <teem/ten.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "ref/superquadric_ref.h"
#include "tensor/glyph.h"
#include "tensor/superquadric.h"

using namespace tg;
using tensor::SuperquadricShape;

namespace {

glm::dvec3 sortedDesc(glm::dvec3 v) {
  if (v.x < v.y) std::swap(v.x, v.y);
  if (v.y < v.z) std::swap(v.y, v.z);
  if (v.x < v.y) std::swap(v.x, v.y);
  return v;
}

}  // namespace

TEST(SuperquadricShape, GammaZeroAndIsotropicGiveEllipsoids) {
  EXPECT_TRUE(tensor::isEllipsoid(tensor::superquadricShape({3, 1, 0.5}, 0.0)));
  EXPECT_TRUE(tensor::isEllipsoid(tensor::superquadricShape({2, 2, 2}, 6.0)));
  EXPECT_TRUE(tensor::isEllipsoid(tensor::superquadricShape({-2, -2, -2}, 6.0)));
  EXPECT_FALSE(tensor::isEllipsoid(tensor::superquadricShape({3, 1, 0.5}, 3.0)));
}

// Kindlmann 2004 as tenGlyphGen computes it, with Teem's own cl1/cp1.
// The renderer's dispatch is two draw ranges over these groups, so each group
// must hold exactly the glyphs the shape rules put there.
TEST(SuperquadricShape, GlyphsAreGroupedStablyWithinTiles) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<float> pos, ten;
  for (int i = 0; i < 300; ++i) {
    // Every fourth tensor is shifted to be positive definite, every fifth is
    // a sphere (signs of both kinds), the rest are random with mixed signs.
    const float shift = i % 4 == 0 ? 2.5f : 0.0f;
    const float t[6] = {shift + u(rng), u(rng), u(rng), shift + u(rng), u(rng), shift + u(rng)};
    const float iso = u(rng);
    const float sphere[6] = {iso, 0, 0, iso, 0, iso};
    ten.insert(ten.end(), i % 5 == 0 ? sphere : t, (i % 5 == 0 ? sphere : t) + 6);
    pos.insert(pos.end(), {float(i), 0.0f, 0.0f});
  }
  const auto set = tensor::buildGlyphs(pos, ten, {}, 1);
  ASSERT_EQ(set.tiles.size(), 2u);  // 256 + 44
  std::size_t mixed = 0;
  for (std::size_t t = 0; t < set.tiles.size(); ++t) {
    const std::size_t first = t * tensor::kTileGlyphs;
    const std::size_t end = std::min(set.glyphs.size(), first + tensor::kTileGlyphs);
    std::uint32_t lastId[3] = {0, 0, 0};
    bool seen[3] = {false, false, false};
    for (std::size_t i = first; i < end; ++i) {
      const auto& g = set.glyphs[i];
      const glm::dvec3 l(g.eigenvalues[0], g.eigenvalues[1], g.eigenvalues[2]);
      const bool sphere = l.x == l.z;
      const auto shape0 = tensor::superquadricShape(l, 0.0), shape3 = tensor::superquadricShape(l, 3.0);
      // A tile holds the inputs of its own index range: tiles keep space coherent.
      EXPECT_GE(g.id, first) << i;
      EXPECT_LT(g.id, end) << i;
      int group = 2;
      if (i < first + set.tiles[t].sphereEnd) {
        group = 0;
        EXPECT_TRUE(sphere && tensor::isEllipsoid(shape3)) << i;
      } else if (i < first + set.tiles[t].definiteEnd) {
        group = 1;
        EXPECT_FALSE(sphere) << i;
        EXPECT_TRUE(l.z > 0 || l.x < 0) << i;
        EXPECT_TRUE(tensor::isEllipsoid(shape0)) << i;
      } else {
        ++mixed;
        EXPECT_TRUE(!sphere && l.z <= 0 && l.x >= 0) << i;
        EXPECT_FALSE(tensor::isEllipsoid(shape0)) << i;
      }
      EXPECT_EQ(int(tensor::glyphGroup(g)), group) << i;
      // Stable: input order is kept within each group.
      if (seen[group]) {
        EXPECT_GT(g.id, lastId[group]) << i;
      }
      seen[group] = true;
      lastId[group] = g.id;
    }
  }
  EXPECT_EQ(set.sphereCount, 60u);
  EXPECT_GT(set.definiteCount, 10u);
  EXPECT_GT(mixed, 10u);
  EXPECT_EQ(set.sphereCount + set.definiteCount + mixed, set.glyphs.size());
}

TEST(SuperquadricShape, PositiveTensorsFollowTeem) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.01, 2.0), gam(0.0, 8.0);
  for (int k = 0; k < 2000; ++k) {
    const glm::dvec3 l = sortedDesc({u(rng), u(rng), u(rng)});
    const double gamma = gam(rng);
    const double ev[3] = {l.x, l.y, l.z};
    const double cl = std::min(0.99, tenAnisoEval_d(ev, tenAniso_Cl1));
    const double cp = std::min(0.99, tenAnisoEval_d(ev, tenAniso_Cp1));
    const SuperquadricShape s = tensor::superquadricShape(l, gamma);
    const double a = std::max(tensor::kMinShapeExponent, std::pow(1 - (cl > cp ? cp : cl), gamma));
    const double b = std::max(tensor::kMinShapeExponent, std::pow(1 - (cl > cp ? cl : cp), gamma));
    EXPECT_EQ(s.axis, cl > cp ? 0 : 2);
    EXPECT_NEAR(s.a, a, 1e-12);
    EXPECT_NEAR(s.b, b, 1e-12);
    EXPECT_EQ(s.c, s.b);
  }
}

TEST(SuperquadricShape, NegativeTensorsMirrorPositiveOnes) {
  const SuperquadricShape p = tensor::superquadricShape({3, 1, 0.5}, 3.0);
  const SuperquadricShape n = tensor::superquadricShape({-0.5, -1, -3}, 3.0);
  EXPECT_DOUBLE_EQ(p.a, n.a);
  EXPECT_DOUBLE_EQ(p.b, n.b);
  EXPECT_EQ(p.axis, 0);
  EXPECT_EQ(n.axis, 2);  // the largest |eigenvalue| is now the last one
}

TEST(SuperquadricShape, MixedSignsBlendSchultzKindlmannShapesContinuously) {
  // At the poles the base shapes appear unblended (Teem's table).
  const SuperquadricShape cone = tensor::superquadricShape({1, 1, 0}, 3.0);  // pole C
  EXPECT_NEAR(cone.a, 1, 1e-12);
  EXPECT_NEAR(cone.b, 2, 1e-12);
  const SuperquadricShape thorn = tensor::superquadricShape({1, 1, -1}, 3.0);  // pole F
  EXPECT_NEAR(thorn.a, 1, 1e-12);
  EXPECT_NEAR(thorn.b, 4, 1e-12);
  EXPECT_NEAR(thorn.c, 4, 1e-12);
  // Continuity across every zone border: a small step changes (a, b, c) little.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 5000; ++k) {
    glm::dvec3 l = sortedDesc({u(rng), u(rng), u(rng)});
    if (l.z > 0 || l.x < 0) continue;
    const glm::dvec3 m = sortedDesc(l + glm::dvec3(u(rng), u(rng), u(rng)) * 1e-7);
    if (m.z > 0 || m.x < 0) continue;
    const SuperquadricShape s = tensor::superquadricShape(l, 3.0), t = tensor::superquadricShape(m, 3.0);
    if (s.axis != t.axis) continue;  // the symmetry axis may flip where the shape is symmetric
    EXPECT_NEAR(s.a, t.a, 1e-4) << l.x << " " << l.y << " " << l.z;
    EXPECT_NEAR(s.b, t.b, 1e-4);
    EXPECT_NEAR(s.c, t.c, 1e-4);
  }
}

TEST(SuperquadricShape, SphericalBarycentricMatchesTeem) {
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0, 1);
  for (int k = 0; k < 1000; ++k) {
    glm::dvec3 p[4];
    for (auto& v : p) v = glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
    p[3] = glm::normalize(std::abs(n(rng)) * p[0] + std::abs(n(rng)) * p[1] + std::abs(n(rng)) * p[2]);
    const glm::dvec3 ours = tensor::sphericalBarycentric(p[0], p[1], p[2], p[3]);
    double bary[3];
    const double a[3] = {p[0].x, p[0].y, p[0].z}, b[3] = {p[1].x, p[1].y, p[1].z}, c[3] = {p[2].x, p[2].y, p[2].z},
                 v[3] = {p[3].x, p[3].y, p[3].z};
    ell_3v_barycentric_spherical_d(bary, a, b, c, v);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(ours[i], bary[i], 1e-9);
  }
}

TEST(SuperquadricGauge, IsTheEuclideanNormForEllipsoidsAndHomogeneous) {
  std::mt19937 rng(11);
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> e(0.002, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const glm::dvec3 p(n(rng), n(rng), n(rng));
    EXPECT_NEAR(tensor::superquadricGauge({}, p), glm::length(p), 1e-12 * glm::length(p));
    const double b = e(rng);
    const SuperquadricShape s{e(rng), b, b, 2};
    const double g = tensor::superquadricGauge(s, p);
    EXPECT_NEAR(tensor::superquadricGauge(s, 3.5 * p), 3.5 * g, 1e-10 * g);
    // Between the inscribed sphere and the circumscribed cube (a, b <= 1).
    EXPECT_LE(g, glm::length(p) * (1 + 1e-12));
    EXPECT_GE(g, std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) * (1 - 1e-12));
  }
}

TEST(SuperquadricGauge, GradientMatchesFiniteDifferencesAndIsFiniteAtZeros) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1, 1), e(0.05, 4.0);
  for (int k = 0; k < 2000; ++k) {
    const SuperquadricShape s{std::min(1.0, e(rng)), e(rng), e(rng), 2};
    const glm::dvec3 p(u(rng), u(rng), u(rng));
    glm::dvec3 grad;
    tensor::superquadricGauge(s, p, &grad);
    for (int i = 0; i < 3; ++i) {
      glm::dvec3 h(0);
      h[i] = 1e-6;
      const double fd = (tensor::superquadricGauge(s, p + h) - tensor::superquadricGauge(s, p - h)) / 2e-6;
      EXPECT_NEAR(grad[i], fd, 1e-4 * std::max(1.0, std::abs(fd))) << i;
    }
  }
  const SuperquadricShape sharp{tensor::kMinShapeExponent, tensor::kMinShapeExponent, tensor::kMinShapeExponent, 2};
  for (const glm::dvec3 p : {glm::dvec3(0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 0.5), glm::dvec3(1, 1, 1),
                             glm::dvec3(0.999, 0.999, 0)}) {
    glm::dvec3 grad;
    const double g = tensor::superquadricGauge(sharp, p, &grad);
    EXPECT_TRUE(std::isfinite(g) && std::isfinite(grad.x) && std::isfinite(grad.y) && std::isfinite(grad.z));
  }
}

TEST(SuperquadricReference, HitsLieOnTheSurfaceAndMissesMissTheBox) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1), e(0.002, 1.0);
  int hits = 0;
  for (int k = 0; k < 3000; ++k) {
    const double b = e(rng);
    const SuperquadricShape s{e(rng), b, b, 2};
    const glm::dvec3 o = 4.0 * glm::dvec3(u(rng), u(rng), u(rng)) + glm::dvec3(0, 0, 5);
    const glm::dvec3 target(0.9 * u(rng), 0.9 * u(rng), 0.9 * u(rng));
    const glm::dvec3 d = target - o;
    double t;
    if (!ref::superquadricFirstHit(s, o, d, 0.0, t)) continue;
    ++hits;
    EXPECT_NEAR(tensor::superquadricGauge(s, o + t * d), 1.0, 1e-9);
    // Nothing of the glyph lies before the hit.
    for (int i = 1; i < 64; ++i) EXPECT_GE(tensor::superquadricGauge(s, o + t * (i / 64.0) * d), 1.0 - 1e-9);
  }
  EXPECT_GT(hits, 1500);  // rays aimed inside the sphere of radius 0.9*sqrt(3) mostly hit
}
