// Tier 3: OSMesa renders against the exact double-precision CPU ray caster,
// on coverage, id, depth and normal.
#include "render_fixture.h"

#include <random>

#include "data-synthetic/generators.h"

using namespace tg;
using test::compare;
using test::GlFixture;
using test::glyphsOf;
using test::cameraFor;
using test::oblique;

namespace {

// Tolerances. Coverage may differ only on edges, where float and double
// round a pixel centre that lies within ~1e-6 of the silhouette either way;
// we allow 1% of glyph pixels there and none in interiors. Depth: the GPU
// computes in float (24-bit mantissa) through a chain of ~10 operations and a
// reversed 32F depth buffer, so 2e-5 relative leaves room above float rounding
// yet catches any wrong root or projection (errors of 1e-3 and more). Normals
// are stored as RGBA16F (11-bit mantissa, < 0.03 deg): median 0.1 deg, and
// 2 deg worst case next to edges of very thin glyphs where the normal turns fast.
const test::Tolerance kTolerance{0.0, 0.01, 0.0, 2e-5, 0.1, 2.0};

void expectMatch(const test::Comparison& c, const char* what) { test::expectWithin(c, kTolerance, what); }

}  // namespace

TEST_F(GlFixture, RandomFieldPerspectiveAndOrtho) {
  const auto set = glyphsOf(synth::randomField(216, 3));
  const double scale = 0.6;
  for (auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
    const auto cam = cameraFor(set, scale, oblique(set, 12.0, proj), 200, 150);
    render::FrameParams p;
    p.scale = scale;
    expectMatch(compare(draw(set, cam, p), ref::renderEllipsoids(cam, set.glyphs, {scale, 0.0}), cam),
                proj == render::Projection::Perspective ? "perspective" : "ortho");
  }
}

TEST_F(GlFixture, ExtremesGallery) {
  const auto set = glyphsOf(synth::extremesGallery(1.0, 1.0));
  const double scale = 1.0;
  const auto cam = cameraFor(set, scale, oblique(set, 40.0, render::Projection::Perspective), 320, 160);
  render::FrameParams p;
  p.scale = scale;
  expectMatch(compare(draw(set, cam, p), ref::renderEllipsoids(cam, set.glyphs, {scale, 0.0}), cam), "extremes");
}

TEST_F(GlFixture, TinyAndHugeWorldsRenderAlike) {
  // Eigenvalues 1e-20 with positions 1e-6, and 1e20 with 1e6: the same picture.
  const auto base = glyphsOf(synth::extremesGallery(1.0, 1.0));
  const auto baseCam = cameraFor(base, 1.0, oblique(base, 40.0, render::Projection::Perspective), 160, 80);
  const auto baseImg = draw(base, baseCam, {});
  for (double k : {1e-6, 1e6}) {
    const auto [set, scale, cam] = test::scaledExtremes(k);
    render::FrameParams p;
    p.scale = scale;
    const auto img = draw(set, cam, p);
    std::size_t differ = 0, covered = 0;
    for (std::size_t i = 0; i < img.id.size(); ++i) {
      differ += img.id[i] != baseImg.id[i];
      covered += baseImg.id[i] != ref::kNoGlyph;
    }
    EXPECT_LE(double(differ), 0.01 * double(covered)) << "world scale " << k;
    expectMatch(compare(img, ref::renderEllipsoids(cam, set.glyphs, {scale, 0.0}), cam), "scaled world");
  }
}

TEST_F(GlFixture, GlyphLargerThanThePointSizeLimitIsWhole) {
  const float pos[3] = {0, 0, 0}, ten[6] = {1, 0, 0, 0.6f, 0, 0.3f};
  const auto set = tensor::buildGlyphs(std::span(pos, 3), std::span(ten, 6), {});
  render::CameraDesc d;
  d.eyeWC = {0.5, -1.2, 2.5};
  d.upWC = {0, 0, 1};
  const auto cam = render::makeCamera(d, 640, 640, glm::dvec3(-1), glm::dvec3(1));
  const auto c = compare(draw(set, cam, {}), ref::renderEllipsoids(cam, set.glyphs, {1.0, 0.0}), cam);
  EXPECT_GT(c.refCovered, 300u * 300u);  // far beyond 255 x 255
  expectMatch(c, "large");
}

TEST_F(GlFixture, CameraInsideAndAcrossTheNearPlane) {
  // The full-viewport fallback and rays that start inside a glyph.
  const auto set = test::glyphsAroundTheEye();
  for (auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
    const auto cam = test::insideCamera(proj);
    expectMatch(compare(draw(set, cam, {}), ref::renderEllipsoids(cam, set.glyphs, {1.0, 0.0}), cam), "inside");
  }
}

TEST_F(GlFixture, FaThresholdHidesGlyphsLikeTheReference) {
  const auto set = glyphsOf(synth::helixPhantom(10, 10, 6).field);
  const double scale = 300;
  const auto cam = cameraFor(set, scale, oblique(set, 30.0, render::Projection::Perspective), 160, 120);
  render::FrameParams p;
  p.scale = scale;
  p.faMin = 0.3;
  const auto img = draw(set, cam, p);
  const auto c = compare(img, ref::renderEllipsoids(cam, set.glyphs, {scale, 0.3}), cam);
  expectMatch(c, "fa threshold");
  p.faMin = 0.0;
  EXPECT_GT(test::compare(draw(set, cam, p), ref::renderEllipsoids(cam, set.glyphs, {scale, 0.0}), cam).refCovered,
            c.refCovered);
}

TEST_F(GlFixture, EmptyAndCulledScenesGiveBackground) {
  const auto set = glyphsOf(synth::randomField(8, 1));
  render::CameraDesc d;
  d.eyeWC = {0, 0, -10};  // looking away from every glyph
  d.lookAtWC = {0, 0, -20};
  const auto cam = render::makeCamera(d, 64, 48, glm::dvec3(-1), glm::dvec3(3));
  render::FrameParams p;
  p.background = {0.25f, 0.5f, 0.75f, 1.0f};
  const auto img = draw(set, cam, p);
  for (std::size_t i = 0; i < img.id.size(); ++i) {
    ASSERT_EQ(img.id[i], ref::kNoGlyph);
    ASSERT_TRUE(std::isinf(img.depth[i]));
    ASSERT_FLOAT_EQ(img.rgba[4 * i + 2], 0.75f);
  }
}
