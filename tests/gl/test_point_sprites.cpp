// Tier 3: point sprites (render/sprite_primitive.h) change what a frame
// costs, never what it shows. Exact equality is the bound: the same shaders
// see the same pixels, since every pixel a point's square adds outside the
// rectangle misses the glyph.
#include "frame_compare.h"
#include "render/raster_glyphs.h"
#include "render_fixture.h"


using namespace tg;
using test::GlFixture;

namespace {

struct Frame {
  render::FrameImage img;
  bool points, indirect;
};

class PointSprites : public GlFixture {
 protected:
  Frame frame(const tensor::GlyphSet& set, const render::Camera& cam, const render::FrameParams& p) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    r.render(cam, p, target);
    return {r.readback(cam, target), render::asRaster(r.glyphPath()).culling().pointSprites(), render::asRaster(r.glyphPath()).culling().indirect()};
  }
};

}  // namespace

// Every kind, both projections, the direct draw and the indirect one (an FA
// threshold compacts, a close camera culls ranges): byte-equal to quads.
TEST_F(PointSprites, FramesEqualTheQuadFrames) {
  const auto set = test::glyphsOf(test::mixedGrid(12, 23));
  ASSERT_GT(set.sphereCount, 0u);
  ASSERT_GT(set.definiteCount, 0u);
  const double scale = 0.45 / set.maxAbsEigenvalue;
  struct Case {
    render::GlyphKind kind;
    double gamma, faMin, dist;
    render::Projection proj;
  };
  const Case cases[] = {{render::GlyphKind::Ellipsoid, 3.0, 0.0, 40.0, render::Projection::Perspective},
                        {render::GlyphKind::Superquadric, 3.0, 0.0, 40.0, render::Projection::Perspective},
                        {render::GlyphKind::Superquadric, 0.0, 0.3, 40.0, render::Projection::Orthographic},
                        {render::GlyphKind::Superquadric, 3.0, 0.0, 20.0, render::Projection::Perspective},
                        {render::GlyphKind::Superquadric, 3.0, 0.0, 80.0, render::Projection::Perspective},
                        {render::GlyphKind::Cylinder, 3.0, 0.3, 40.0, render::Projection::Perspective},
                        {render::GlyphKind::Box, 3.0, 0.0, 40.0, render::Projection::Orthographic}};
  int direct = 0, indirect = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(int(c.kind) * 100 + int(c.gamma) * 10 + int(c.dist));
    const auto cam = test::cameraFor(set, scale, test::oblique(set, c.dist, c.proj), 200, 150);
    render::FrameParams p;
    p.scale = scale;
    p.glyph = c.kind;
    p.gamma = c.gamma;
    p.faMin = c.faMin;
    p.orientedSprites = false;  // wide glyphs would draw quads (test_oriented_sprites.cpp)
    const Frame points = frame(set, cam, p);
    p.pointSprites = false;
    const Frame quads = frame(set, cam, p);
    EXPECT_TRUE(points.points);
    EXPECT_FALSE(quads.points);
    EXPECT_EQ(points.indirect, quads.indirect);
    (points.indirect ? indirect : direct) += 1;
    EXPECT_GT(test::coveredPixels(quads.img), 1000u);
    EXPECT_EQ(test::differingPixels(points.img, quads.img), 0u);
  }
  EXPECT_GT(direct, 0);
  EXPECT_GT(indirect, 0);
}

// A glyph that could outgrow the point size cap is drawn as quads: the eye
// among the glyphs.
TEST_F(PointSprites, TheEyeAmongTheGlyphsDrawsQuads) {
  const auto set = test::glyphsOf(test::mixedGrid(12, 23));
  const double scale = 0.45 / set.maxAbsEigenvalue;
  render::CameraDesc d = test::oblique(set, 40.0, render::Projection::Perspective);
  d.eyeWC = 0.5 * (set.boundsMinWC + set.boundsMaxWC);
  d.lookAtWC = d.eyeWC + glm::dvec3(1.0, 0.2, 0.1);
  const auto cam = test::cameraFor(set, scale, d, 200, 150);
  render::FrameParams p = test::superquadricParams(scale);
  const Frame f = frame(set, cam, p);
  EXPECT_FALSE(f.points);
  EXPECT_GT(test::coveredPixels(f.img), 1000u);
}
