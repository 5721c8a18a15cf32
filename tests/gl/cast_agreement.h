#pragma once
// Tier 3 helpers: how a glyph path that casts rays outside GL's rasteriser
// (the CPU path, render/cpu_glyphs.h; the compute path,
// render/compute_glyphs.h) agrees with the raster path on a frame. All run
// the same intersection source (shaders/lib/ellipsoid.glsl and the
// superquadric march's files, as GLSL on llvmpipe, the CPU path as C++ over
// GLM), so that the pictures agree to float rounding (the compute path's,
// the same GLSL through the same compiler, measured equal to the raster
// path's at every pixel):
// - coverage and ids: equal at every pixel centre (measured: no pixel differs
//   on any scene here). A pixel centre within float rounding of a silhouette
//   (the hit test's h = 1 - |q|^2 within a few ulps of 0) or of a depth tie
//   could go either way where llvmpipe contracts a * b + c into one rounding
//   (FMA) and the C++ rounds twice: one pixel in 10^4 is allowed for that;
// - depth: 2e-5 of the depth (perspective) or of the depth range
//   (orthographic: a linear depth buffer), the unit and bound test_render.cpp
//   holds the raster path to against the double reference. The view depth
//   tc + t is summed from terms that may be far larger than it (a ray from
//   inside a glyph, the far wall), and llvmpipe's division, square root and
//   FMA contraction round those terms otherwise than the C++ does, by a few
//   float ulps (6e-8) of the largest; measured up to 1.3e-5;
// - normals: 0.05 degrees (both stored as RGBA16F: 11-bit mantissas, < 0.03
//   degrees, plus the rounding of the hit point);
// - lit colour: 2e-3, below one 8-bit step (3.9e-3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "render_fixture.h"

namespace tg::test {

constexpr double kIdMismatch = 1e-4, kRelDepth = 2e-5, kNormalDeg = 0.05, kColor = 2e-3;
// Pixels where the paths keep different glyphs whose hits lie at the same
// depth (within kRelDepth): exact ties, such as the coplanar faces of a
// stress field's mirrored boxes, which the order rule settles only when both
// paths round the two depths alike (measured: 8 of 2,719 box pixels of the
// point load, none elsewhere); 1% allows for that.
constexpr double kDepthTies = 1e-2;
// The march at its default tolerance (eps 1e-4 of the glyph's size): each
// path stops within eps of the root, and rounding may stop them an
// iteration apart, so their depths may differ by 2 eps of a glyph's size,
// which here is below its depth (measured up to 8.3e-5, a glyph around the
// eye). With a tight march (eps 1e-6) kRelDepth holds.
// Normals: the gradient at points that far apart, on shapes whose normal
// turns fast near their edges (gamma 1000: exponents of 2e-3): measured up
// to 0.087 degrees; test_superquadric.cpp's 0.5 against the reference.
constexpr double kRelDepthMarch = 2e-4, kNormalDegMarch = 0.5;

// `cpu`: the frame of the path under test.
struct Pair {
  render::FrameImage raster, cpu;
  std::uint64_t cpuDrawn = 0;
};

struct Agreement {
  std::size_t covered = 0, idMismatch = 0, depthTies = 0;
  double relDepth = 0, normalDeg = 0, color = 0;
};

inline Agreement agreement(const Pair& s, const render::Camera& cam) {
  const bool ortho = cam.desc.projection == render::Projection::Orthographic;
  Agreement g;
  const auto& a = s.raster;
  const auto& b = s.cpu;
  for (std::size_t i = 0; i < a.id.size(); ++i) {
    g.covered += a.id[i] != ref::kNoGlyph ? 1 : 0;
    if (a.id[i] != b.id[i]) {
      // Two glyphs' surfaces at one depth (mirrored boxes' coplanar faces):
      // which one a path keeps is rounding's choice, and both are right.
      const bool tie = a.id[i] != ref::kNoGlyph && b.id[i] != ref::kNoGlyph &&
                       std::abs(a.depth[i] - b.depth[i]) <= kRelDepth * (ortho ? cam.farVC - cam.nearVC : double(a.depth[i]));
      ++(tie ? g.depthTies : g.idMismatch);
      continue;
    }
    for (int k = 0; k < 3; ++k) g.color = std::max(g.color, double(std::abs(a.rgba[4 * i + k] - b.rgba[4 * i + k])));
    if (a.id[i] == ref::kNoGlyph) continue;
    const double unit = ortho ? cam.farVC - cam.nearVC : double(a.depth[i]);
    g.relDepth = std::max(g.relDepth, double(std::abs(a.depth[i] - b.depth[i])) / unit);
    const glm::dvec3 na(a.normalWC[3 * i], a.normalWC[3 * i + 1], a.normalWC[3 * i + 2]);
    const glm::dvec3 nb(b.normalWC[3 * i], b.normalWC[3 * i + 1], b.normalWC[3 * i + 2]);
    const double c = std::clamp(glm::dot(na, nb) / (glm::length(na) * glm::length(nb)), -1.0, 1.0);
    g.normalDeg = std::max(g.normalDeg, glm::degrees(std::acos(c)));
  }
  return g;
}

// `marched`: a superquadric frame at the default march tolerance.
inline void expectAgree(const Pair& s, const render::Camera& cam, const std::string& what, std::size_t minCovered = 500,
                 bool marched = false, double maxColor = kColor) {
  SCOPED_TRACE(what);
  const Agreement g = agreement(s, cam);
  std::printf("[ cast path ] %s: %zu covered, %zu id mismatches, %zu depth ties, depth %.2g, normal %.3g deg, colour %.2g\n",
              what.c_str(), g.covered, g.idMismatch, g.depthTies, g.relDepth, g.normalDeg, g.color);
  EXPECT_GE(g.covered, minCovered);
  EXPECT_LE(double(g.idMismatch), kIdMismatch * double(g.covered));
  EXPECT_LE(double(g.depthTies), kDepthTies * double(g.covered));
  EXPECT_LT(g.relDepth, marched ? kRelDepthMarch : kRelDepth);
  EXPECT_LT(g.normalDeg, marched ? kNormalDegMarch : kNormalDeg);
  EXPECT_LT(g.color, maxColor);
}

inline tensor::GlyphSet grid(std::uint32_t n, std::uint64_t seed) { return test::glyphsOf(test::mixedGrid(n, seed)); }

}  // namespace tg::test
