// Tier 3: llvmpipe's per-frame pixel cull (shaders/cull_pixels.comp) drops
// glyphs that no pixel centre can see before the draw: it changes which
// glyphs reach the vertex stage, never the image.
#include "frame_compare.h"
#include "render/raster_glyphs.h"
#include "render_fixture.h"

#include <string_view>

#include "render/renderer_profile.h"
#include "render/sprite_primitive.h"

using namespace tg;
using test::GlFixture;

namespace {

struct Frame {
  render::FrameImage img;
  std::uint64_t drawn, pixelCulls;
};

class PixelCull : public GlFixture {
 protected:
  void SetUp() override {
    ctx_->makeCurrent();
    const auto* name = reinterpret_cast<const char*>(ctx_->api().GetString(GL_RENDERER));
    if (!(render::RendererProfile::of(name ? name : "").pixelCullMaxPx > 0.0)) GTEST_SKIP() << "no pixel cull on " << name;
  }
  Frame frame(const tensor::GlyphSet& set, const render::Camera& cam, const render::FrameParams& p) {
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    r.render(cam, p, target);
    return {r.readback(cam, target), r.drawnGlyphs(), render::asRaster(r.glyphPath()).culling().passes().pixelCulls};
  }
};

}  // namespace

// Every kind, both projections, with and without a threshold and a slab:
// the culled frame equals the full one byte for byte, and drew fewer glyphs.
TEST_F(PixelCull, FramesEqualTheUnculledFrames) {
  const auto set = test::glyphsOf(test::mixedGrid(16, 41, 0.1));
  ASSERT_GT(set.sphereCount, 0u);
  ASSERT_GT(set.definiteCount, 0u);
  const double scale = 0.03 / set.maxAbsEigenvalue;
  struct Case {
    render::GlyphKind kind;
    double gamma, faMin;
    int slabAxis;
    render::Projection proj;
  };
  const Case cases[] = {{render::GlyphKind::Ellipsoid, 3.0, 0.0, -1, render::Projection::Perspective},
                        {render::GlyphKind::Superquadric, 3.0, 0.0, -1, render::Projection::Perspective},
                        {render::GlyphKind::Superquadric, 0.0, 0.3, -1, render::Projection::Orthographic},
                        {render::GlyphKind::Superquadric, 3.0, 0.2, 2, render::Projection::Perspective},
                        {render::GlyphKind::Box, 3.0, 0.0, -1, render::Projection::Orthographic}};
  for (const Case& c : cases) {
    SCOPED_TRACE(int(c.kind) * 100 + int(c.gamma) * 10 + int(c.proj));
    const auto cam = test::cameraFor(set, scale, test::oblique(set, 40.0, c.proj), 320, 240);
    render::FrameParams p;
    p.scale = scale;
    p.glyph = c.kind;
    p.gamma = c.gamma;
    p.faMin = c.faMin;
    if (c.slabAxis >= 0) p.slab = {c.slabAxis, 3.0, 11.0};
    const Frame culled = frame(set, cam, p);
    p.pixelCull = false;
    const Frame full = frame(set, cam, p);
    EXPECT_EQ(culled.pixelCulls, 1u);
    EXPECT_EQ(full.pixelCulls, 0u);
    // Some glyphs are seen, and most are culled.
    EXPECT_GT(test::coveredPixels(full.img), 10u);
    EXPECT_GT(culled.drawn, 0u);
    EXPECT_LT(2 * culled.drawn, full.drawn);
    EXPECT_EQ(test::differingPixels(culled.img, full.img), 0u);
  }
}

// The cull overwrites the threshold's kept list: a later frame without it
// compacts again and draws every glyph above the threshold.
TEST_F(PixelCull, ALaterThresholdFrameCompactsAgain) {
  const auto set = test::glyphsOf(test::mixedGrid(16, 41, 0.1));
  const double scale = 0.03 / set.maxAbsEigenvalue;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 40.0, render::Projection::Perspective), 320, 240);
  render::FrameParams p = test::superquadricParams(scale);
  p.faMin = 0.3;
  p.pixelCull = false;
  const Frame reference = frame(set, cam, p);
  render::GlyphRenderer r(ctx_->api(), *lib_);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(set);
  r.render(cam, p, target);
  p.pixelCull = true;
  r.render(cam, p, target);
  const std::uint64_t culled = r.drawnGlyphs();
  p.pixelCull = false;
  r.render(cam, p, target);
  EXPECT_LT(culled, reference.drawn);
  EXPECT_EQ(r.drawnGlyphs(), reference.drawn);
  EXPECT_EQ(test::differingPixels(r.readback(cam, target), reference.img), 0u);
}

// Glyphs of many pixels run no cull pass: the feature costs them nothing.
TEST_F(PixelCull, WideGlyphsRunNoPass) {
  const auto set = test::glyphsOf(test::mixedGrid(16, 41, 0.1));
  const double scale = 0.45 / set.maxAbsEigenvalue;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 40.0, render::Projection::Perspective), 320, 240);
  render::FrameParams p = test::superquadricParams(scale);
  const Frame f = frame(set, cam, p);
  EXPECT_EQ(f.pixelCulls, 0u);
  EXPECT_EQ(f.drawn, set.glyphs.size());
}
