// Tier 1: the bound that decides point sprites (render/sprite_primitive.h)
// holds every glyph's clamped screen rectangle, checked against the
// rectangles of the box corners the sprite programs project.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <glm/vec4.hpp>

#include "render/renderer_profile.h"
#include "render/sprite_primitive.h"

using namespace tg;

namespace {

// The clamped pixel width and height of the rectangle of `corners` points
// (WC), as lib/sprite.glsl draws it; 0 when culled, -1 when a point is behind the eye.
glm::dvec2 clampedRectPx(const render::Camera& cam, const std::vector<glm::dvec3>& cornersWC) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const auto& c : cornersWC) {
    const glm::dvec4 cc = cam.projVCCC * cam.viewWCVC * glm::dvec4(c, 1.0);
    if (cc.w <= 0.0) return glm::dvec2(-1.0);
    const glm::dvec2 ndc(cc.x / cc.w, cc.y / cc.w);
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  lo = glm::clamp(lo, -1.0, 1.0);
  hi = glm::clamp(hi, -1.0, 1.0);
  if (lo.x >= hi.x || lo.y >= hi.y) return glm::dvec2(0.0);
  return {0.5 * (hi.x - lo.x) * cam.width, 0.5 * (hi.y - lo.y) * cam.height};
}

}  // namespace

TEST(SpriteBound, HoldsEveryRandomGlyphBoxAndIsNotFarAbove) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.0, 1.0);
  int checked = 0;
  double tightest = std::numeric_limits<double>::infinity();
  for (int trial = 0; trial < 400; ++trial) {
    const bool ortho = trial % 4 == 3;
    render::CameraDesc d;
    d.lookAtWC = {u(rng), u(rng), u(rng)};
    d.eyeWC = d.lookAtWC + (2.0 + 6.0 * pos(rng)) * glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3);
    d.upWC = {0, 0, 1};
    d.fovYDeg = 10.0 + 100.0 * pos(rng);
    d.projection = ortho ? render::Projection::Orthographic : render::Projection::Perspective;
    d.orthoHeight = 3.0;
    const glm::dvec3 lo(-1.0), hi(1.0);
    const double radius = 0.02 + 0.3 * pos(rng);
    const auto cam = render::makeCamera(d, 320 + trial % 7 * 50, 240, lo - radius, hi + radius);
    const double bound = render::spriteSizeBoundPx(cam, lo, hi, radius);
    if (!std::isfinite(bound)) continue;
    double widest = 0;
    for (int g = 0; g < 200; ++g) {
      // A box of half-diagonal `radius` about a centre in [lo, hi], rotated.
      const glm::dvec3 c(u(rng), u(rng), u(rng));
      glm::dvec3 e[3];
      const glm::dvec3 a = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3);
      const glm::dvec3 b = glm::normalize(glm::cross(a, glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3));
      const glm::dvec3 axes = glm::dvec3(pos(rng), pos(rng), pos(rng)) + 1e-3;
      const double k = radius / glm::length(axes);
      e[0] = a * axes.x * k, e[1] = b * axes.y * k, e[2] = glm::cross(a, b) * axes.z * k;
      std::vector<glm::dvec3> corners;
      for (int q = 0; q < 8; ++q) corners.push_back(c + ((q & 1) ? e[0] : -e[0]) + ((q & 2) ? e[1] : -e[1]) + ((q & 4) ? e[2] : -e[2]));
      const glm::dvec2 px = clampedRectPx(cam, corners);
      ASSERT_GE(px.x, 0.0) << "a corner behind the eye under a finite bound";
      EXPECT_LE(std::max(px.x, px.y), bound) << "trial " << trial;
      widest = std::max(widest, std::max(px.x, px.y));
      ++checked;
    }
    if (widest > 4.0) tightest = std::min(tightest, bound / widest);
  }
  EXPECT_GT(checked, 40000);
  // Not so loose that points are never drawn: within a small factor somewhere.
  EXPECT_LT(tightest, 3.0);
}

TEST(SpriteBound, NoneWhenTheEyeIsWithinReach) {
  render::CameraDesc d;
  d.eyeWC = {0, 0, 0.5};
  d.lookAtWC = {0, 0, 0};
  const glm::dvec3 lo(-1.0), hi(1.0);
  const auto cam = render::makeCamera(d, 320, 240, lo - 0.1, hi + 0.1);
  EXPECT_FALSE(std::isfinite(render::spriteSizeBoundPx(cam, lo, hi, 0.1)));
  EXPECT_FALSE(render::pointSpritesFit(cam, lo, hi, 0.1, 255.0));
  // Far away the same glyphs fit.
  d.eyeWC = {0, 0, 40};
  const auto far = render::makeCamera(d, 320, 240, lo - 0.1, hi + 0.1);
  EXPECT_TRUE(render::pointSpritesFit(far, lo, hi, 0.1, 255.0));
  EXPECT_FALSE(render::pointSpritesFit(far, lo, hi, 0.1, 1.0));
}

// Each choice keyed by the GL implementation: llvmpipe's measured values,
// under any LLVM version or vector width in its name; any other renderer
// the plain path (points, no pixel cull, the pre-pass always, one draw).
TEST(RendererProfile, LlvmpipeTakesItsMeasuredChoicesAndOthersThePlainPath) {
  for (const char* name : {"llvmpipe (LLVM 15.0.6, 256 bits)", "llvmpipe (LLVM 19.1.7, 128 bits)"}) {
    const auto p = tg::render::RendererProfile::of(name);
    EXPECT_EQ(p.orientedQuadMinPx, 14.0) << name;
    EXPECT_EQ(p.pixelCullMaxPx, 1.0) << name;
    EXPECT_EQ(p.occlusionMinPx, 4.0) << name;
    EXPECT_EQ(p.glyphsPerSubmit, 4096u) << name;
  }
  for (const char* name : {"NVIDIA H200/PCIe/SSE2", "AMD Radeon Graphics (radeonsi, navi21, LLVM 15.0.6)", ""}) {
    const auto p = tg::render::RendererProfile::of(name);
    EXPECT_EQ(p.orientedQuadMinPx, HUGE_VAL) << name;
    EXPECT_EQ(p.pixelCullMaxPx, 0.0) << name;
    EXPECT_EQ(p.occlusionMinPx, 0.0) << name;
    EXPECT_EQ(p.glyphsPerSubmit, tg::render::RendererProfile::kWholeDraw) << name;
  }
}
