// Tier 1: glyph size (tensor/glyph_scale.h): the magnitude mappings keep each
// glyph's shape ratios, the clamp bounds every glyph, the defaults resolve
// as documented, and the framing box ignores a few outlying points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "data-synthetic/generators.h"
#include "tensor/glyph_scale.h"

using namespace tg;
using tensor::Magnitude;

namespace {

// Indefinite tensors over eight decades of magnitude: a heavy tail.
tensor::GlyphSet heavyTailed(std::size_t n) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<float> pos, ten;
  for (std::size_t i = 0; i < n; ++i) {
    const double mag = std::pow(10.0, 4.0 * u(rng));
    for (int k = 0; k < 3; ++k) pos.push_back(float(i % 10) + float(k == 1) * float(i / 10));
    for (int k = 0; k < 6; ++k) ten.push_back(float(mag * u(rng)));
  }
  return tensor::buildGlyphs(pos, ten, {}, 1);
}

double magnitude(const tensor::GlyphRecord& g) {
  return std::max(std::abs(double(g.eigenvalues[0])), std::abs(double(g.eigenvalues[2])));
}

}  // namespace

TEST(GlyphScale, MappingsAndClampKeepEveryGlyphsShapeRatios) {
  const auto set = heavyTailed(500);
  for (const Magnitude m : {Magnitude::Linear, Magnitude::Log, Magnitude::Shape}) {
    for (const double clamp : {0.0, 3.0}) {
      SCOPED_TRACE(std::string(tensor::magnitudeName(m)) + " clamp " + std::to_string(clamp));
      const tensor::SizeMapping s{m, 2.0, clamp};
      std::size_t clamped = 0;
      for (const auto& g : set.glyphs) {
        const glm::dvec3 a = tensor::glyphAxes(g, 0.5, s), full = tensor::ellipsoidAxes(g, 1.0);
        const double r = std::max({a.x, a.y, a.z}), rf = std::max({full.x, full.y, full.z});
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k] / r, full[k] / rf, 1e-12);
        EXPECT_NEAR(r, tensor::glyphRadiusWC(0.5, s, magnitude(g)), 1e-12 * r);
        if (clamp > 0.0) {
          EXPECT_LE(r, clamp * (1 + 1e-12));
        }
        clamped += clamp > 0.0 && r >= clamp * (1 - 1e-12);
      }
      // The field spans eight decades: linear and log glyphs reach the clamp.
      if (clamp > 0.0 && m != Magnitude::Shape) {
        EXPECT_GT(clamped, 10u);
      }
    }
  }
}

TEST(GlyphScale, LinearUnclampedIsTodaysGlyphBitForBit) {
  const auto set = heavyTailed(200);
  for (const auto& g : set.glyphs) EXPECT_EQ(tensor::glyphAxes(g, 0.37, {}), tensor::ellipsoidAxes(g, 0.37));
}

TEST(GlyphScale, MagnitudeMappingsFollowTheirDefinitions) {
  const tensor::SizeMapping log{Magnitude::Log, 3.0, 0.0}, shape{Magnitude::Shape, 3.0, 0.0};
  EXPECT_DOUBLE_EQ(tensor::mappedMagnitude(log, 3.0), 3.0 * std::log(2.0));
  EXPECT_NEAR(tensor::mappedMagnitude(log, 1e-9), 1e-9, 1e-17);  // linear below the knee
  double prev = 0.0;
  for (double m = 1e-6; m < 1e8; m *= 3.7) {
    const double f = tensor::mappedMagnitude(log, m);
    EXPECT_GT(f, prev);
    EXPECT_LE(f, m);
    prev = f;
    EXPECT_DOUBLE_EQ(tensor::mappedMagnitude(shape, m), 3.0);
    EXPECT_DOUBLE_EQ(tensor::glyphRadiusWC(2.0, shape, m), 6.0);
  }
  // Ten decades of magnitude become about twenty times the knee.
  EXPECT_LT(tensor::mappedMagnitude(log, 3e10), 25.0 * 3.0);
  EXPECT_EQ(tensor::mappedMagnitude(log, 0.0), 0.0);
}

TEST(GlyphScale, DefaultsResolveAsDocumented) {
  const auto set = heavyTailed(1000);
  const auto sample = tensor::sampleMagnitudes(set, 0.5);
  ASSERT_EQ(sample.sorted.size(), set.glyphs.size());
  std::vector<double> m;
  for (const auto& g : set.glyphs) m.push_back(magnitude(g));
  std::sort(m.begin(), m.end());
  const double p90 = m[std::size_t(0.9 * double(m.size() - 1) + 0.5)], median = m[m.size() / 2];

  const tensor::ResolvedScale d = tensor::resolveScale({}, sample);
  EXPECT_DOUBLE_EQ(d.scale * p90, 0.25);  // that glyph is one spacing (0.5) across
  EXPECT_DOUBLE_EQ(d.mapping.maxRadiusWC, 0.5);  // clamped at 2 spacings across
  EXPECT_EQ(d.mapping.magnitude, Magnitude::Linear);
  EXPECT_GT(d.clampedFraction, 0.0);
  EXPECT_LT(d.clampedFraction, 0.1);  // only above the 90th percentile, at twice its size
  EXPECT_NE(d.why.find("clamp 2 sample spacings"), std::string::npos) << d.why;
  EXPECT_DOUBLE_EQ(tensor::defaultScale(set, 0.5), d.scale);

  tensor::ScaleParams p;
  p.mode = tensor::ScaleMode::Absolute;
  p.factor = 4.0;
  const auto a = tensor::resolveScale(p, sample);
  EXPECT_EQ(a.scale, 2.0);  // ParaView's ScaleFactor: the diameter per eigenvalue unit
  EXPECT_EQ(a.mapping.maxRadiusWC, 0.0);  // absolute: no clamp unless asked
  p.clampSpacings = 3.0;
  EXPECT_DOUBLE_EQ(tensor::resolveScale(p, sample).mapping.maxRadiusWC, 0.75);

  p = {};
  p.mode = tensor::ScaleMode::Max;
  p.clampSpacings = 0.0;
  const auto mx = tensor::resolveScale(p, sample);
  EXPECT_DOUBLE_EQ(mx.scale * set.maxAbsEigenvalue, 0.25);
  EXPECT_EQ(mx.mapping.maxRadiusWC, 0.0);
  EXPECT_NE(mx.why.find("no clamp"), std::string::npos) << mx.why;

  p = {};
  p.magnitude = Magnitude::Log;
  const auto lg = tensor::resolveScale(p, sample);
  EXPECT_DOUBLE_EQ(lg.mapping.lambda0, median);  // the knee at the median glyph
  EXPECT_NEAR(tensor::glyphRadiusWC(lg.scale, lg.mapping, p90), 0.25, 1e-12);
  p.lambda0 = 5.0;
  EXPECT_EQ(tensor::resolveScale(p, sample).mapping.lambda0, 5.0);

  p = {};
  p.magnitude = Magnitude::Shape;
  const auto sh = tensor::resolveScale(p, sample);
  for (double x : {m.front(), median, m.back()})
    if (x > 0) {
      EXPECT_NEAR(tensor::glyphRadiusWC(sh.scale, sh.mapping, x), 0.25, 1e-12);
    }
  EXPECT_EQ(sh.clampedFraction, 0.0);  // every glyph is one spacing: under the clamp
}

TEST(GlyphScale, LogAndClampMakeASingularFieldsGlyphsVisible) {
  // Boussinesq's point load: stresses grow as 1/r^2 towards the load.
  const io::TensorField f = synth::boussinesq(16, 0.3);
  const auto set = tensor::buildGlyphs(f.positions, f.tensors, f.ids, 1);
  const auto sample = tensor::sampleMagnitudes(set, f.sampleSpacing);
  auto shareAbove = [&](const tensor::ScaleParams& p, double spacings) {
    const auto r = tensor::resolveScale(p, sample);
    std::size_t n = 0;
    for (double m : sample.sorted) n += 2.0 * tensor::glyphRadiusWC(r.scale, r.mapping, m) >= spacings * f.sampleSpacing;
    return double(n) / double(sample.sorted.size());
  };
  tensor::ScaleParams maxMode;
  maxMode.mode = tensor::ScaleMode::Max;
  maxMode.clampSpacings = 0.0;
  tensor::ScaleParams logMode;
  logMode.magnitude = Magnitude::Log;
  // Sized by the largest glyph, almost all are under a tenth of a spacing.
  EXPECT_LT(shareAbove(maxMode, 0.1), 0.05);
  EXPECT_GT(shareAbove({}, 0.1), 0.5);
  EXPECT_GT(shareAbove(logMode, 0.25), 0.9);
}

TEST(GlyphScale, FramingIgnoresAFewOutlyingPointsOnly) {
  std::vector<float> pos, ten;
  for (int i = 0; i < 1000; ++i) {
    pos.insert(pos.end(), {float(i % 10), float((i / 10) % 10), float(i / 100)});
    ten.insert(ten.end(), {1, 0, 0, 1, 0, 1});
  }
  const auto dense = tensor::buildGlyphs(pos, ten, {}, 1);
  auto box = tensor::framingBox(dense, true, 0.5);
  EXPECT_EQ(box.lo, glm::dvec3(-0.5));
  EXPECT_EQ(box.hi, glm::dvec3(9.5));
  // Three points far out: a scattered set frames the rest, a grid frames all.
  for (int k = 0; k < 3; ++k) {
    pos.insert(pos.end(), {1000.0f + float(k), 5, 5});
    ten.insert(ten.end(), {1, 0, 0, 1, 0, 1});
  }
  const auto stray = tensor::buildGlyphs(pos, ten, {}, 1);
  box = tensor::framingBox(stray, true, 0.0);
  EXPECT_LE(box.hi.x, 9.0);
  EXPECT_NE(box.why.find("percentile"), std::string::npos) << box.why;
  EXPECT_EQ(tensor::framingBox(stray, false, 0.0).hi.x, 1002.0);
}

TEST(GlyphScale, ZeroTensorsDoNotSetTheScale) {
  // A volume that is mostly background: 90% zero tensors, as Slicer's
  // estimated helix is outside the phantom.
  std::vector<float> pos, ten;
  for (int i = 0; i < 1000; ++i) {
    pos.insert(pos.end(), {float(i % 10), float((i / 10) % 10), float(i / 100)});
    const float v = i % 10 == 0 ? 2e-3f : 0.0f;
    ten.insert(ten.end(), {v, 0, 0, v / 2, 0, v / 4});
  }
  const auto set = tensor::buildGlyphs(pos, ten, {}, 1);
  const auto r = tensor::resolveScale({}, tensor::sampleMagnitudes(set, 1.0));
  EXPECT_NEAR(r.scale * 2e-3, 0.5, 1e-6);  // the drawn glyphs are one spacing across (2e-3 in float)
}

TEST(GlyphScale, FramingLeavesOutZeroTensors) {
  // A 10^3 grid whose tensors are zero but in the block [2, 4] x [3, 6] x
  // [1, 2], as a DTI volume's brain sits in its zero background: the view
  // frames that block, not the grid. Built on several threads, so that the
  // per-thread bounds are merged.
  std::vector<float> pos, ten;
  for (int i = 0; i < 1000; ++i) {
    const int x = i % 10, y = (i / 10) % 10, z = i / 100;
    pos.insert(pos.end(), {float(x), float(y), float(z)});
    const bool in = x >= 2 && x <= 4 && y >= 3 && y <= 6 && z >= 1 && z <= 2;
    const float v = in ? 1.0f : 0.0f;
    ten.insert(ten.end(), {v, 0, 0, v / 2, 0, v / 4});
  }
  const auto set = tensor::buildGlyphs(pos, ten, {}, 4);
  EXPECT_EQ(set.boundsMaxWC, glm::dvec3(9.0));
  for (bool scattered : {false, true}) {
    const auto box = tensor::framingBox(set, scattered, 0.5);
    EXPECT_EQ(box.lo, glm::dvec3(1.5, 2.5, 0.5));
    EXPECT_EQ(box.hi, glm::dvec3(4.5, 6.5, 2.5));
    EXPECT_NE(box.why.find("not zero"), std::string::npos) << box.why;
  }
  // An eigenvalue floor gives the zero tensors a size: they are drawn, and framed.
  tensor::GlyphOptions floor;
  floor.minEigenvalue = 1e-3;
  const auto floored = tensor::buildGlyphs(pos, ten, {}, 4, floor);
  EXPECT_EQ(tensor::framingBox(floored, false, 0.0).hi, glm::dvec3(9.0));
  EXPECT_EQ(tensor::framingBox(floored, false, 0.0).why.find("not zero"), std::string::npos);
}
