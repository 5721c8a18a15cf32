// Tier 3: quads along a glyph's projected axes (shaders/lib/sprite.glsl)
// change what a frame costs, never what it shows. Exact equality is the
// bound, as for point sprites: every pixel that can hit lies in both the
// axis-aligned rectangle and the oriented quad, with the same margin.
#include "frame_compare.h"
#include "render/raster_glyphs.h"
#include "render_fixture.h"

#include <random>
#include <string>
#include <utility>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "render/renderer_profile.h"
#include "render/sprite_primitive.h"

using namespace tg;
using test::GlFixture;

namespace {

// A 10^3 grid of thin glyphs in random orientations: needles, discs, spheres
// (each 7th) and mixed signs (each 5th), so that every dispatch group is
// drawn; or needles only.
io::TensorField thinGrid(bool needlesOnly = false) {
  io::TensorField f;
  std::mt19937_64 rng(41);
  std::normal_distribution<double> n(0.0, 1.0);
  for (std::uint32_t i = 0; i < 10 * 10 * 10; ++i) {
    glm::dvec3 l = i % 2 == 0 ? glm::dvec3(1.0, 0.06, 0.04) : glm::dvec3(1.0, 0.9, 0.05);
    if (needlesOnly) l = glm::dvec3(1.0, 0.06, 0.04);
    else if (i % 7 == 0) l = glm::dvec3(0.6);
    else if (i % 5 == 0) l.z = -0.3;
    const glm::dmat3 r = glm::mat3_cast(glm::normalize(glm::dquat(n(rng), n(rng), n(rng), n(rng))));
    const glm::dmat3 t = r * glm::dmat3(l.x, 0, 0, 0, l.y, 0, 0, 0, l.z) * glm::transpose(r);
    const double t9[9] = {t[0][0], t[1][0], t[2][0], t[0][1], t[1][1], t[2][1], t[0][2], t[1][2], t[2][2]};
    const double p[3] = {double(i % 10), double(i / 10 % 10), double(i / 100)};
    f.addFull(i, p, t9);
  }
  return f;
}

struct Frame {
  render::FrameImage img;
  bool points;
  GLuint64 fragments;  // fragment shader runs, the lighting pass's included
};

class OrientedSprites : public GlFixture {
 protected:
  Frame frame(const tensor::GlyphSet& set, const render::Camera& cam, const render::FrameParams& p) {
    ctx_->makeCurrent();
    const gl::Api& gl = ctx_->api();
    render::GlyphRenderer r(gl, *lib_);
    render::GBuffer target(gl, cam.width, cam.height);
    r.upload(set);
    const GLuint64 fragments = test::countedBy(gl, GL_FRAGMENT_SHADER_INVOCATIONS, [&] { r.render(cam, p, target); });
    return {r.readback(cam, target), render::asRaster(r.glyphPath()).culling().pointSprites(), fragments};
  }
  // The same frame drawn as quads along the glyphs' projected outlines and
  // as axis-aligned quads (point sprites off in both).
  std::pair<Frame, Frame> orientedAndRects(const tensor::GlyphSet& set, const render::Camera& cam,
                                           render::FrameParams p) {
    p.pointSprites = false;
    p.orientedSprites = true;
    Frame oriented = frame(set, cam, p);
    p.orientedSprites = false;
    return {std::move(oriented), frame(set, cam, p)};
  }
};

}  // namespace

// Quad frames, every kind that ray casts, both projections, the direct draw
// and the indirect one (an FA threshold compacts, a close camera culls
// ranges): byte-equal to the axis-aligned quads, with fewer fragments shaded.
TEST_F(OrientedSprites, FramesEqualTheRectangleFramesWithFewerFragments) {
  const auto set = test::glyphsOf(thinGrid());
  const double scale = 0.45 / set.maxAbsEigenvalue;
  struct Case {
    render::GlyphKind kind;
    double gamma, faMin, dist;
    render::Projection proj;
  };
  const Case cases[] = {{render::GlyphKind::Ellipsoid, 3.0, 0.0, 25.0, render::Projection::Perspective},
                        {render::GlyphKind::Superquadric, 3.0, 0.0, 25.0, render::Projection::Perspective},
                        {render::GlyphKind::Superquadric, 0.0, 0.3, 25.0, render::Projection::Orthographic},
                        {render::GlyphKind::Superquadric, 3.0, 0.0, 9.0, render::Projection::Perspective},
                        {render::GlyphKind::Ellipsoid, 3.0, 0.5, 40.0, render::Projection::Orthographic}};
  for (const Case& c : cases) {
    SCOPED_TRACE(int(c.kind) * 1000 + int(c.gamma) * 100 + int(c.dist));
    const auto cam = test::cameraFor(set, scale, test::oblique(set, c.dist, c.proj), 480, 360);
    render::FrameParams p;
    p.scale = scale;
    p.glyph = c.kind;
    p.gamma = c.gamma;
    p.faMin = c.faMin;
    const auto [oriented, rects] = orientedAndRects(set, cam, p);
    EXPECT_FALSE(oriented.points);
    EXPECT_GT(test::coveredPixels(rects.img), 1000u);
    EXPECT_EQ(test::differingPixels(oriented.img, rects.img), 0u);
    EXPECT_LT(oriented.fragments, rects.fragments);
  }
}

// Needles at random angles fill a small part of their rectangles: the
// oriented quads shade far fewer fragments (llvmpipe counts whole 4x4
// blocks, the lighting pass's included).
TEST_F(OrientedSprites, NeedlesShadeFarFewerFragments) {
  const auto set = test::glyphsOf(thinGrid(true));
  const double scale = 0.45 / set.maxAbsEigenvalue;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 25.0, render::Projection::Perspective), 480, 360);
  render::FrameParams p = test::superquadricParams(scale);
  const auto [oriented, rects] = orientedAndRects(set, cam, p);
  EXPECT_EQ(test::differingPixels(oriented.img, rects.img), 0u);
  const double lighting = double(cam.width) * cam.height;
  EXPECT_LT(double(oriented.fragments) - lighting, 0.7 * (double(rects.fragments) - lighting));
}

// The frame's primitive by the typical sprite's width: on llvmpipe, wide
// glyphs draw oriented quads instead of points, and show the same pixels.
TEST_F(OrientedSprites, WideGlyphsDrawQuadsOnLlvmpipe) {
  const auto set = test::glyphsOf(thinGrid());
  const double scale = 0.45 / set.maxAbsEigenvalue;
  ctx_->makeCurrent();
  const auto* name = reinterpret_cast<const char*>(ctx_->api().GetString(GL_RENDERER));
  const double minPx = render::RendererProfile::of(name ? name : "").orientedQuadMinPx;
  for (const int width : {160, 640}) {
    SCOPED_TRACE(width);
    const auto cam = test::cameraFor(set, scale, test::oblique(set, 25.0, render::Projection::Perspective), width,
                                     width * 3 / 4);
    render::FrameParams p = test::superquadricParams(scale);
    const Frame chosen = frame(set, cam, p);
    p.orientedSprites = false;
    const Frame points = frame(set, cam, p);
    EXPECT_TRUE(points.points);
    const double typicalPx = render::typicalSpritePx(cam, set.boundsMinWC, set.boundsMaxWC,
                                                     1.0 / tensor::defaultScale(set, 1.0) * scale);
    EXPECT_EQ(chosen.points, typicalPx < minPx);
    if (std::string(name ? name : "").find("llvmpipe") != std::string::npos) {
      EXPECT_EQ(chosen.points, width == 160);
    }
    EXPECT_EQ(test::differingPixels(chosen.img, points.img), 0u);
  }
}

// Mixed-sign glyphs long along one axis, in random orientations: their
// quads follow the outline of the double pyramid that holds them (a rhombus
// between its apexes, or its square), with a sixteenth of a pixel of margin.
// Every pixel that can hit lies in it: byte-equal to the rectangles' frames,
// perspective and orthographic, near and far; and the quads shade far fewer
// fragments than the rectangles. So does the point load at world scale 1e-6
// and 1e6, where rounding in GC is coarsest.
TEST_F(OrientedSprites, MixedSignOutlinesHoldEveryPixelWithFewerFragments) {
  io::TensorField f;
  std::mt19937_64 rng(43);
  std::normal_distribution<double> n(0.0, 1.0);
  const glm::dvec3 kinds[] = {{1.0, -0.06, -0.04}, {1.0, -0.9, 0.05}, {0.05, 0.04, -1.0}, {0.5, -0.02, -1.0}};
  for (std::uint32_t i = 0; i < 8 * 8 * 8; ++i) {
    const glm::dvec3 l = kinds[i % 4];
    const glm::dmat3 r = glm::mat3_cast(glm::normalize(glm::dquat(n(rng), n(rng), n(rng), n(rng))));
    const glm::dmat3 t = r * glm::dmat3(l.x, 0, 0, 0, l.y, 0, 0, 0, l.z) * glm::transpose(r);
    const double t9[9] = {t[0][0], t[1][0], t[2][0], t[0][1], t[1][1], t[2][1], t[0][2], t[1][2], t[2][2]};
    const double p[3] = {double(i % 8), double(i / 8 % 8), double(i / 64)};
    f.addFull(i, p, t9);
  }
  const auto set = test::glyphsOf(f);
  ASSERT_EQ(set.sphereCount + set.definiteCount, 0u);
  const double scale = 0.45 / set.maxAbsEigenvalue;
  struct Case {
    double gamma, dist;
    render::Projection proj;
  };
  for (const Case c : {Case{3.0, 20.0, render::Projection::Perspective}, Case{0.0, 7.0, render::Projection::Perspective},
                       Case{8.0, 20.0, render::Projection::Orthographic}}) {
    SCOPED_TRACE(int(c.gamma) * 100 + int(c.dist));
    const auto cam = test::cameraFor(set, scale, test::oblique(set, c.dist, c.proj), 480, 360);
    render::FrameParams p = test::superquadricParams(scale, c.gamma);
    const auto [outlines, rects] = orientedAndRects(set, cam, p);
    EXPECT_GT(test::coveredPixels(rects.img), 2000u);
    EXPECT_EQ(test::differingPixels(outlines.img, rects.img), 0u);
    const double lighting = double(cam.width) * cam.height;
    EXPECT_LT(double(outlines.fragments) - lighting, 0.7 * (double(rects.fragments) - lighting));
  }
  for (const double k : {1e-6, 1e6}) {
    SCOPED_TRACE(k);
    // The point load's field (data-synthetic/generators.cpp), k times as large.
    io::TensorField load;
    for (std::uint32_t i = 0; i < 6 * 6 * 6; ++i) {
      const double h = 2.0 / 6, q[3] = {-1.0 + (0.5 + i % 6) * h, -1.0 + (0.5 + i / 6 % 6) * h, -2.0 + (0.5 + i / 36) * h};
      double t9[9];
      synth::boussinesqStress(q[0], q[1], -q[2], 0.3, t9);
      const double p[3] = {k * q[0], k * q[1], k * q[2]};
      load.addFull(i, p, t9);
    }
    const auto scaled = test::glyphsOf(load);
    tensor::ScaleParams sized;
    sized.percentile = 0.9;
    const double sc = tensor::resolveScale(sized, tensor::sampleMagnitudes(scaled, k * 2.0 / 6)).scale;
    const auto cam = test::cameraFor(scaled, sc, test::oblique(scaled, 3.0 * k, render::Projection::Perspective), 320, 240);
    render::FrameParams p = test::superquadricParams(sc);
    const auto [outlines, rects] = orientedAndRects(scaled, cam, p);
    EXPECT_GT(test::coveredPixels(rects.img), 1000u);
    EXPECT_EQ(test::differingPixels(outlines.img, rects.img), 0u);
    EXPECT_LT(outlines.fragments, rects.fragments);
  }
}

TEST(SpritePrimitive, TypicalWidthScalesWithTheViewport) {
  render::CameraDesc d;
  d.eyeWC = {0, 0, 10};
  d.lookAtWC = {0, 0, 0};
  d.upWC = {0, 1, 0};
  d.fovYDeg = 90;
  const auto cam = render::makeCamera(d, 200, 100, glm::dvec3(-1), glm::dvec3(1));
  // tan(45 deg) = 1: 100 rows span 2 * 10 world units at depth 10.
  EXPECT_NEAR(render::typicalSpritePx(cam, glm::dvec3(-1), glm::dvec3(1), 1.0), 5.0, 1e-9);
  d.eyeWC = {0, 0, -10};
  d.lookAtWC = {0, 0, -20};
  const auto behind = render::makeCamera(d, 200, 100, glm::dvec3(-1), glm::dvec3(1));
  EXPECT_EQ(render::typicalSpritePx(behind, glm::dvec3(-1), glm::dvec3(1), 1.0), HUGE_VAL);
}

// The extremes gallery (discs and needles down to 1e-6, zero eigenvalues,
// mixed signs) large enough on screen for oriented quads and the pyramid
// outlines of mixed-sign glyphs, at world scales 1e-6, 1 and 1e6 and gammas
// 0, 3 and 50: the same frames as rectangles.
TEST_F(OrientedSprites, ExtremeGlyphOutlinesHoldEveryPixel) {
  for (const double k : {1e-6, 1.0, 1e6}) {
    const double eigenScale = k > 1 ? 1e20 : k < 1 ? 1e-20 : 1.0;
    const auto set = test::glyphsOf(synth::extremesGallery(eigenScale, k));
    const double scale = k / eigenScale;
    const auto cam = test::cameraFor(set, scale, test::oblique(set, 25.0 * k, render::Projection::Perspective), 640, 320);
    for (const double gamma : {0.0, 3.0, 50.0}) {
      SCOPED_TRACE(::testing::Message() << "k " << k << " gamma " << gamma);
      const auto [outlines, rects] = orientedAndRects(set, cam, test::superquadricParams(scale, gamma));
      EXPECT_GT(test::coveredPixels(rects.img), 2000u);
      EXPECT_EQ(test::differingPixels(outlines.img, rects.img), 0u);
      EXPECT_LT(outlines.fragments, rects.fragments);
    }
  }
}
