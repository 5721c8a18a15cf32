// Tier 3: every row of the glyph kind table (render/glyph_kind.h) drawn on
// OSMesa against the row's own CPU reference, so that a new row is checked
// by its reference with no new test code; each kind's own file holds the
// finer cases.
#include "render/raster_glyphs.h"
#include "render_fixture.h"

using namespace tg;
using test::GlFixture;

namespace {

// The loosest of the kinds' own bounds (test_prism.cpp): silhouettes may go
// either way on 1% of the covered pixels, no interior pixel may; depth 2e-5
// relative; normals by median and 99th percentile (a box's or cylinder's
// edge pixel may take either face's normal).
const test::Tolerance kTolerance{0.0, 0.01, 0.0, 2e-5, 0.1, 180.0};
// Blobs against their untruncated reference: truncation (cutoff 1e-3)
// moves the surface where the sum's slope along the ray is small, on
// grazing rays: measured 5.8e-5 of the depth at most here.
const test::Tolerance kBlobTolerance{0.0, 0.01, 0.0, 1e-4, 0.1, 180.0};

}  // namespace

TEST_F(GlFixture, EveryKindMatchesItsRowsReference) {
  const auto set = test::glyphsOf(synth::randomField(48, 5));
  const double scale = 0.6, gamma = 3.0;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 9.0, render::Projection::Perspective), 160, 120);
  for (const render::GlyphKindInfo& k : render::glyphKinds()) {
    render::FrameParams p = test::superquadricParams(scale, gamma);
    p.glyph = k.kind;
    p.march = {30, 1e-6};  // the method, not the speed trade of looser settings
    const test::Comparison c = test::compare(draw(set, cam, p), k.reference(cam, set.glyphs, {scale, 0.0}, gamma), cam);
    test::expectWithin(c, k.kind == render::GlyphKind::Blob ? kBlobTolerance : kTolerance, std::string(k.name));
    EXPECT_LT(c.normalDeg.p99, 2.0) << k.name;
  }
}

// A frame builds the closed-form program of its own kind and of no other.
TEST_F(GlFixture, AFrameBuildsOnlyItsKindsProgram) {
  const auto set = test::glyphsOf(synth::randomField(8, 3));
  const auto cam = test::cameraFor(set, 0.6, test::oblique(set, 9.0, render::Projection::Orthographic), 64, 48);
  for (const render::GlyphKindInfo& k : render::glyphKinds()) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    render::FrameParams p;
    p.scale = 0.6;
    p.glyph = k.kind;
    if (!render::pathDraws("raster", k.kind)) continue;  // blobs: the cpu path (test_cpu_glyphs.cpp)
    r.render(cam, p, target);
    for (const render::GlyphKindInfo& other : render::glyphKinds()) {
      if (other.draw != render::KindDraw::ClosedForm) continue;
      EXPECT_EQ(render::asRaster(r.glyphPath()).kindBuilt(other.kind), other.kind == k.kind) << k.name << " built " << other.name;
    }
  }
}
