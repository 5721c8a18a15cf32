// Tier 1: shaders/lib's intersection, bounds and normal code compiled as C++
// (render/glsl_cpp.h), as the CPU glyph path runs it (render::castGlyphs),
// against src/ref's double-precision ray casters. No GL: the same source
// the GPU runs is checked here in float against double, with test_render's
// raster-path tolerances (tests/gl/test_render.cpp says why), but for the
// normals, which here skip the G-buffer's RGBA16F storage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "data-synthetic/generators.h"
#include "ref/ellipsoid_ref.h"
#include "ref/image_diff.h"
#include "ref/superquadric_ref.h"
#include "render/cpu_glyphs.h"
#include "render/glsl_cpp.h"
#include "render/tile_binning.h"
#include "tensor/superquadric.h"
#include "cpu_frame.h"
#include "thin_glyphs.h"

using namespace tg;

namespace {

tensor::GlyphSet glyphsOf(const io::TensorField& f) { return tensor::buildGlyphs(f.positions, f.tensors, f.ids); }

render::Camera cameraFor(const tensor::GlyphSet& s, double scale, render::Projection proj, int w, int h) {
  render::CameraDesc d;
  d.lookAtWC = 0.5 * (s.boundsMinWC + s.boundsMaxWC);
  d.eyeWC = d.lookAtWC + 12.0 * glm::normalize(glm::dvec3(0.7, -1.1, 0.9));
  d.upWC = {0, 0, 1};
  d.projection = proj;
  d.orthoHeight = 0.9 * 12.0;
  const auto [lo, hi] = tensor::glyphBoxWC(s, scale);
  return render::makeCamera(d, w, h, lo, hi);
}

// test_superquadric.cpp's view of the extremes gallery.
render::Camera galleryCamera(const tensor::GlyphSet& s, render::Projection proj) {
  render::CameraDesc d;
  d.lookAtWC = 0.5 * (s.boundsMinWC + s.boundsMaxWC);
  d.eyeWC = d.lookAtWC + 40.0 * glm::normalize(glm::dvec3(0.7, -1.1, 0.9));
  d.upWC = {0, 0, 1};
  d.projection = proj;
  d.orthoHeight = 0.9 * 40.0;
  const auto [lo, hi] = tensor::glyphBoxWC(s, 1.0);
  return render::makeCamera(d, 320, 160, lo, hi);
}

}  // namespace

TEST(CpuCasts, SharedIntersectionMatchesTheReference) {
  const tensor::GlyphSet set = glyphsOf(synth::randomField(216, 3));
  const double scale = 0.6;
  for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
    SCOPED_TRACE(proj == render::Projection::Perspective ? "perspective" : "orthographic");
    const auto cam = cameraFor(set, scale, proj, 200, 150);
    render::FrameParams p;
    p.scale = scale;
    for (const int threads : {1, 3}) {
      render::CpuCasts casts;
      const std::uint64_t drawn = render::castGlyphs(set.glyphs, cam, p, false, threads, casts);
      EXPECT_GT(drawn, 100u);
      const ref::ImageDiff d =
          ref::diffImages(test::asFrame(casts, set, cam), ref::renderEllipsoids(cam, set.glyphs, {scale, 0.0}), cam);
      const double covered = double(d.refCovered);
      EXPECT_GT(d.refCovered, 5000u);
      EXPECT_EQ(d.interiorMismatch, 0u);
      EXPECT_LE(double(d.coverageMismatch), 0.01 * covered);
      EXPECT_EQ(d.idMismatch, 0u);
      EXPECT_LT(d.depth.max, 2e-5);
      EXPECT_LT(d.normalDeg.median, 0.01);
      EXPECT_LT(d.normalDeg.max, 2.0);
    }
  }
}

// The superquadric march compiled as C++, every variant, against the
// bracketed double-precision reference at gamma 0 (definite glyphs cast as
// ellipsoids), 3 and 20, with a tight march and test_superquadric.cpp's
// tolerances (which say why): the shapes' maths is shared with the GLSL, so
// that this checks the raster path's source too. On the random field and on
// the extremes gallery without its glyphs of a zero (or 1e-6) eigenvalue:
// those are 1e-7 of their size thick (kMinAxisRatio), the march's GC
// coordinates reach 1e6 on them, where float resolves a quarter unit of a
// glyph two units thick, and a few of their pixels go either way
// (SuperquadricExtremesMatchTheRasterPath measures how many).
TEST(CpuCasts, SharedSuperquadricMarchMatchesTheReference) {
  const tensor::GlyphSet random = glyphsOf(synth::randomField(64, 21));
  const tensor::GlyphSet extremes = test::withoutFlatGlyphs(synth::extremesGallery(1.0, 1.0));
  for (const tensor::GlyphSet* set : {&random, &extremes}) {
    const double scale = set == &random ? 0.6 : 1.0;
    for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
      const auto cam = set == &random ? cameraFor(*set, scale, proj, 200, 150) : galleryCamera(*set, proj);
      for (const double gamma : {0.0, 3.0, 20.0}) {
        SCOPED_TRACE(std::string(set == &random ? "random" : "extremes") + ", gamma " + std::to_string(gamma));
        render::FrameParams p;
        p.scale = scale;
        p.glyph = render::GlyphKind::Superquadric;
        p.gamma = gamma;
        p.march = {30, 1e-6};
        render::CpuCasts casts;
        render::castGlyphs(set->glyphs, cam, p, false, 2, casts);
        const ref::ImageDiff d = ref::diffImages(test::asFrame(casts, *set, cam),
                                                 ref::renderSuperquadrics(cam, set->glyphs, {scale, 0.0}, gamma), cam);
        EXPECT_GT(d.refCovered, 500u);
        EXPECT_EQ(d.interiorMismatch, 0u);
        EXPECT_LE(double(d.coverageMismatch), 0.01 * double(d.refCovered));
        EXPECT_EQ(d.idMismatch, 0u);
        EXPECT_LT(d.depth.max, 1e-5);
        EXPECT_LT(d.normalDeg.median, 0.05);
        EXPECT_LT(d.normalDeg.max, 0.5);
      }
    }
  }
}

// The screen rectangle: the C++-compiled ellipsoidRectNDC against the
// reference's double-precision Sigg et al. eq. (5).
TEST(CpuCasts, SharedRectangleMatchesTheReference) {
  const tensor::GlyphSet set = glyphsOf(synth::randomField(64, 5));
  const double scale = 0.6;
  const auto cam = cameraFor(set, scale, render::Projection::Perspective, 320, 240);
  render::FrameParams p;
  p.scale = scale;
  render::glsl::Shaders sh;
  sh.setCamera(cam);
  sh.setGlyph(p);
  int checked = 0;
  for (const tensor::GlyphRecord& g : set.glyphs) {
    render::glsl::GlyphRecord r;
    std::memcpy(&r, &g, sizeof r);
    const ref::RectNDC want = ref::ellipsoidRectNDC(cam, g, scale);
    if (want.full) continue;
    const glm::vec3 axes = sh.glyphAxes(glm::vec3(r.eigenvalues_id));
    const glm::mat3 rotVC = glm::mat3(sh.uViewWCVC) * sh.quatToMat3(r.frameWC);
    const glm::vec3 centreVC = glm::vec3(sh.uViewWCVC * glm::vec4(glm::vec3(r.posWC_fa), 1.0f));
    const glm::mat4 tVC = sh.ellipsoidTVC(rotVC, axes, centreVC);
    glm::vec4 rect, byRows;
    ASSERT_TRUE(sh.ellipsoidRectNDC(sh.uProjVCCC * tVC, rect));
    // What the sprites take: the same rows, a projection row at a time.
    ASSERT_TRUE(sh.ellipsoidFrameRectNDC(glm::mat3(tVC), centreVC, byRows));
    // A 64th of a pixel: the margin the raster path allows for the rounding.
    const double tolX = 2.0 / 320 / 64, tolY = 2.0 / 240 / 64;
    for (const glm::vec4& got : {rect, byRows}) {
      EXPECT_NEAR(got.x, want.xmin, tolX);
      EXPECT_NEAR(got.z, want.xmax, tolX);
      EXPECT_NEAR(got.y, want.ymin, tolY);
      EXPECT_NEAR(got.w, want.ymax, tolY);
    }
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

// Lean frames (past CpuCasts::keptSetUpBytes: a bounding sphere first, the
// sprite set up only in the tiles that cast it) cast what kept frames do,
// bit for bit: every kind and group, both projections, and anti-aliasing's
// masked casts. The depth test picks one hit per pixel whatever the order.
TEST(CpuCasts, LeanFramesCastWhatKeptFramesCast) {
  const tensor::GlyphSet random = glyphsOf(synth::randomField(343, 8));
  const tensor::GlyphSet extremes = test::withoutFlatGlyphs(synth::extremesGallery(1.0, 1.0));
  struct Kind {
    render::GlyphKind kind;
    double gamma;
  };
  const Kind kinds[] = {{render::GlyphKind::Ellipsoid, 0.0}, {render::GlyphKind::Superquadric, 0.0},
                        {render::GlyphKind::Superquadric, 3.0}, {render::GlyphKind::Superquadric, 20.0},
                        {render::GlyphKind::Cylinder, 0.0}, {render::GlyphKind::Box, 0.0}};
  std::size_t compared = 0;
  for (const tensor::GlyphSet* set : {&random, &extremes})
    for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic})
      for (const Kind& k : kinds)
        for (const bool masked : {false, true}) {
          const double scale = set == &random ? 0.6 : 1.0;
          const auto cam = set == &random ? cameraFor(*set, scale, proj, 200, 150) : galleryCamera(*set, proj);
          SCOPED_TRACE(std::string(set == &random ? "random" : "extremes") + ", kind " + std::to_string(int(k.kind)) +
                       ", gamma " + std::to_string(k.gamma) + (masked ? ", masked" : ""));
          render::FrameParams p;
          p.scale = scale;
          p.glyph = k.kind;
          p.gamma = k.gamma;
          render::CpuCasts kept, lean;
          lean.keptSetUpBytes = 0;
          if (masked)
            for (render::CpuCasts* c : {&kept, &lean}) {
              c->only.assign(std::size_t(cam.width) * std::size_t(cam.height), 0);
              for (std::size_t i = 0; i < c->only.size(); i += 3) c->only[i] = 1;
            }
          render::castGlyphs(set->glyphs, cam, p, true, 2, kept);
          const std::uint64_t leanReached = render::castGlyphs(set->glyphs, cam, p, true, 3, lean);
          EXPECT_GE(leanReached, kept.count) << "a bounding sphere reaches every pixel its glyph's sprite does";
          std::size_t hits = 0, differ = 0;
          for (std::size_t i = 0; i < kept.record.size(); ++i) {
            if (kept.record[i] != lean.record[i]) ++differ;
            if (kept.record[i] == 0 || kept.record[i] != lean.record[i]) continue;
            ++hits;
            if (kept.windowDepth[i] != lean.windowDepth[i] || kept.normalWC[i] != lean.normalWC[i] ||
                kept.hitGC[i] != lean.hitGC[i])
              ++differ;
          }
          EXPECT_EQ(differ, 0u);
          EXPECT_GT(hits, masked ? 200u : 600u);
          compared += hits;
        }
  EXPECT_GT(compared, 100000u);
}

// Tile bins hold each rectangle in every tile it touches, in index order,
// whatever the number of parts.
TEST(CpuCasts, TileBinsHoldEachRectangleInOrder) {
  const std::vector<render::PixelRect> rects = {{0, 0, 0, 0}, {10, 10, 40, 20}, {15, 0, 16, 69}, {0, 0, 99, 69}};
  for (const int parts : {1, 2, 5}) {
    render::TileBins b;
    render::binToTiles(rects, 100, 70, parts, b);
    ASSERT_EQ(b.tilesX, 7);
    ASSERT_EQ(b.tilesY, 5);
    for (std::size_t t = 0; t < b.tiles(); ++t) {
      const int tx = int(t % 7), ty = int(t / 7);
      std::vector<std::uint32_t> want;
      for (std::uint32_t i = 0; i < rects.size(); ++i) {
        const auto& r = rects[i];
        if (r.x0 / 16 <= tx && tx <= r.x1 / 16 && r.y0 / 16 <= ty && ty <= r.y1 / 16) want.push_back(i);
      }
      const std::vector<std::uint32_t> got(b.items.begin() + b.start[t], b.items.begin() + b.start[t + 1]);
      EXPECT_EQ(got, want) << "tile " << t << ", " << parts << " parts";
    }
  }
}

// The runs the CPU path writes into GL's targets cover each pixel of a
// tile that holds an item once, and no other pixel, at sizes that are and
// are not whole tiles.
TEST(CpuCasts, TileRunsCoverExactlyTheTilesThatHoldItems) {
  const std::vector<render::PixelRect> rects = {{0, 0, 0, 0}, {40, 10, 60, 12}, {15, 30, 16, 69}, {99, 60, 99, 69},
                                                render::kNoPixels, {70, 0, 70, 0}};
  for (const auto& [w, h] : {std::pair{100, 70}, std::pair{96, 64}}) {
    std::vector<render::PixelRect> clipped;
    for (render::PixelRect r : rects)
      if (r.x0 < w && r.y0 < h)
        clipped.push_back({r.x0, r.y0, std::uint16_t(std::min<int>(r.x1, w - 1)), std::uint16_t(std::min<int>(r.y1, h - 1))});
      else if (r.x0 > r.x1)
        clipped.push_back(r);
    render::TileBins b;
    render::binToTiles(clipped, w, h, 2, b);
    std::vector<render::PixelRect> runs;
    render::tileRuns(b, w, h, runs);
    std::vector<int> covered(std::size_t(w) * std::size_t(h), 0);
    for (const render::PixelRect& r : runs) {
      ASSERT_LE(r.x0, r.x1);
      ASSERT_LE(r.y0, r.y1);
      ASSERT_LT(r.x1, w);
      ASSERT_LT(r.y1, h);
      for (int y = r.y0; y <= r.y1; ++y)
        for (int x = r.x0; x <= r.x1; ++x) ++covered[std::size_t(y) * std::size_t(w) + std::size_t(x)];
    }
    std::size_t held = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t t = std::size_t(y / render::kTilePx) * std::size_t(b.tilesX) + std::size_t(x / render::kTilePx);
        const int want = b.start[t] != b.start[t + 1] ? 1 : 0;
        held += std::size_t(want);
        EXPECT_EQ(covered[std::size_t(y) * std::size_t(w) + std::size_t(x)], want) << x << ", " << y << " of " << w << " x " << h;
      }
    EXPECT_GT(held, 5u * 256u);
    EXPECT_LT(held, std::size_t(w) * std::size_t(h) / 2);
  }
}

// The gauge alone (the blobs' sums), compiled as C++, against the gauge with
// its gradient (the march's) and the double-precision one, over shapes from
// the sharpest exponent to 4, with zero, equal and tiny coordinates: within
// float rounding of both.
TEST(CpuCasts, SharedGaugeValueMatchesTheGauge) {
  render::glsl::Shaders sh;
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(-1.5f, 1.5f), e(0.0f, 1.0f);
  double worst = 0, worstRef = 0, gaugeRef = 0;
  for (int k = 0; k < 200000; ++k) {
    // Exponents log-uniform in [kMinShapeExponent, 4].
    auto exponent = [&] { return float(tensor::kMinShapeExponent * std::pow(4.0 / tensor::kMinShapeExponent, e(rng))); };
    const glm::vec3 shape(std::min(1.0f, exponent()), exponent(), exponent());
    glm::vec3 p(u(rng), u(rng), u(rng));
    if (k % 5 == 0) p[k % 3] = 0.0f;
    if (k % 7 == 0) p.y = p.x;
    if (k % 11 == 0) p.x *= 1e-20f;
    glm::vec3 grad;
    const double g = sh.superquadricGauge(shape, p, grad), v = sh.superquadricGaugeValue(shape, p);
    const double want = tensor::superquadricGauge({shape.x, shape.y, shape.z, 2}, glm::dvec3(p));
    // Far outside a sharp shape the gauge passes float's range: both alike.
    ASSERT_EQ(std::isfinite(v), std::isfinite(g)) << k;
    if (!std::isfinite(g) || !(want < 1e30)) continue;
    worst = std::max(worst, std::abs(v - g) / std::max(g, 1e-30));
    worstRef = std::max(worstRef, std::abs(v - want) / std::max(want, 1e-30));
    gaugeRef = std::max(gaugeRef, std::abs(g - want) / std::max(want, 1e-30));
  }
  std::printf("[ gauge ] value alone against the gauge: %.2g; against the double gauge: %.2g (the gauge's own: %.2g), relative\n",
              worst, worstRef, gaugeRef);
  // Measured 6.9e-7, and 7.7e-6 against the double gauge, as the float gauge itself.
  EXPECT_LT(worst, 4e-6);
  EXPECT_LT(worstRef, 1.5 * gaugeRef);
  EXPECT_EQ(sh.superquadricGaugeValue(glm::vec3(0.5f, 0.5f, 0.5f), glm::vec3(0.0f)), 0.0f);
}
