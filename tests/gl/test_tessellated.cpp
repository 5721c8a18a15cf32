// Tier 3: the tessellated baseline converges to the exact superquadric as its
// resolution grows, so `bench scale` compares like with like.
#include "render/raster_glyphs.h"
#include "render_fixture.h"

#include "data-synthetic/generators.h"

using namespace tg;
using test::GlFixture;

TEST_F(GlFixture, TessellatedBaselineConvergesToTheReference) {
  const auto set = test::glyphsOf(synth::randomField(64, 3));
  const double scale = 0.6, gamma = 3.0;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 12.0, render::Projection::Perspective), 240, 180);
  const ref::RefImage reference = ref::renderSuperquadrics(cam, set.glyphs, {scale, 0.0}, gamma);
  double previous = 1.0;
  for (int r : {8, 16, 64}) {
    SCOPED_TRACE(r);
    render::FrameParams p = test::superquadricParams(scale, gamma);
    p.tessellation = r;
    const auto c = test::compare(draw(set, cam, p), reference, cam);
    ASSERT_GT(c.refCovered, 5000u);
    const double error = double(c.coverageMismatch) / double(c.refCovered);
    EXPECT_LT(error, previous);
    previous = error;
  }
  // At 64 x 64 the polygon's chords sit within a pixel of the surface here.
  EXPECT_LT(previous, 0.02);
}

// The baseline's program is compiled by its first frame, never by a
// ray-cast one, and takes the frame's parameters when it is: a renderer that
// drew other frames first gives the same image as a fresh one.
TEST_F(GlFixture, TessellatedProgramIsBuiltByTheFirstTessellatedFrame) {
  const auto set = test::glyphsOf(synth::randomField(64, 3));
  const auto cam = test::cameraFor(set, 0.6, test::oblique(set, 12.0, render::Projection::Perspective), 120, 90);
  render::FrameParams p = test::superquadricParams(0.6, 1.5);
  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(set);
  r.render(cam, p, target);
  EXPECT_FALSE(render::asRaster(r.glyphPath()).tessellatedProgramBuilt());
  p.gamma = 3.0;
  p.tessellation = 16;
  r.render(cam, p, target);
  EXPECT_TRUE(render::asRaster(r.glyphPath()).tessellatedProgramBuilt());
  const auto late = r.readback(cam, target);
  const auto fresh = draw(set, cam, p);
  ASSERT_EQ(late.id.size(), fresh.id.size());
  EXPECT_GT(std::count_if(late.id.begin(), late.id.end(), [](std::uint32_t id) { return id != ref::kNoGlyph; }), 500);
  EXPECT_TRUE(late.id == fresh.id);
  EXPECT_TRUE(late.rgba == fresh.rgba);
}
