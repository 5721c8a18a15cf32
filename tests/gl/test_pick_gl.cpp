// Tier 3: picking on a real GL frame. The one-pixel read (render::readPixel)
// against the full readback of the same frame, and what a context item's id
// resolves to.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "app/pick.h"
#include "render/pixel_probe.h"
#include "render_fixture.h"

namespace {

using tg::test::GlFixture;

class PickGl : public GlFixture {};

// A context item that draws nothing, so that the frame holds glyphs alone;
// it reports a label and a value that depends on the point it is asked at.
class Probe : public tg::render::ContextItem {
 public:
  std::string label() const override { return "probe plane"; }
  void drawOpaque(const tg::render::Camera&, const tg::render::FrameParams&, std::uint32_t,
                  tg::render::ContextTarget) override {}
  std::pair<glm::dvec3, glm::dvec3> boundsWC() const override { return {glm::dvec3(0.0), glm::dvec3(0.0)}; }
  std::optional<double> valueAt(const glm::dvec3& p) const override { return 2.0 * p.x + p.y - p.z; }
  std::size_t gpuBytes() const override { return 0; }
};

}  // namespace

// Every pixel of a perspective frame of a random field: the one-pixel read
// gives the id and view depth that the full readback gives (depth to float
// rounding: both convert the same stored window depth, one in float).
TEST_F(PickGl, OnePixelReadsMatchTheFullReadback) {
  const tg::io::TensorField field = tg::synth::randomField(300, 7);
  const tg::tensor::GlyphSet set = tg::test::glyphsOf(field);
  const double scale = 0.6;
  const auto cam =
      tg::test::cameraFor(set, scale, tg::test::oblique(set, 30.0, tg::render::Projection::Perspective), 96, 72);
  ctx_->makeCurrent();
  tg::render::GlyphRenderer r(ctx_->api(), *lib_);
  tg::render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(set);
  tg::render::FrameParams p;
  p.scale = scale;
  r.render(cam, p, target);
  const tg::render::FrameImage img = r.readback(cam, target);
  std::size_t glyphPixels = 0;
  for (int j = 0; j < cam.height; ++j)
    for (int i = 0; i < cam.width; ++i) {
      const tg::render::PixelSample s = tg::render::readPixel(ctx_->api(), cam, target, i, j);
      const std::size_t k = std::size_t(j) * std::size_t(cam.width) + std::size_t(i);
      ASSERT_EQ(s.id, img.id[k]) << i << " " << j;
      if (s.id == 0xFFFFFFFFu) {
        EXPECT_TRUE(std::isinf(s.viewDepth));
      } else {
        ++glyphPixels;
        EXPECT_NEAR(s.viewDepth, double(img.depth[k]), 1e-6 * double(img.depth[k]));
      }
    }
  EXPECT_GT(glyphPixels, 500u);
  EXPECT_THROW(tg::render::readPixel(ctx_->api(), cam, target, cam.width, 0), std::out_of_range);
  EXPECT_THROW(tg::render::readPixel(ctx_->api(), cam, target, 0, -1), std::out_of_range);
}

// A context id names the item in its slot: the pick carries its label and
// its value at the surface point, the pixel centre's ray at the given depth.
// An id past the items, or an input index no tensor has, is a logic error.
TEST_F(PickGl, ContextIdsResolveToTheirItem) {
  tg::io::TensorField field = tg::synth::randomField(20, 3);
  const std::uint32_t firstId = field.ids[0];
  tg::app::PickTable table(field, {});
  ctx_->makeCurrent();
  tg::render::GlyphRenderer r(ctx_->api(), *lib_);
  r.addContext(std::make_unique<Probe>());
  tg::render::CameraDesc d;
  d.eyeWC = {1, 2, 10};
  d.lookAtWC = {1, 2, 0};
  const auto cam = tg::render::makeCamera(d, 64, 48, glm::dvec3(-1), glm::dvec3(1));
  const tg::app::Pick p = tg::app::resolvePick(cam, {40, 10}, tg::render::kContextIdBase, 9.5, table, r);
  ASSERT_TRUE(p.context);
  EXPECT_FALSE(p.glyph);
  EXPECT_EQ(p.context->label, "probe plane");
  const tg::render::RayWC ray = cam.rayThroughPixel(40.5, 10.5);
  const glm::dvec3 s = ray.origin + 9.5 * ray.direction;
  ASSERT_TRUE(p.surfaceWC);
  EXPECT_NEAR(glm::length(*p.surfaceWC - s), 0.0, 1e-12);
  EXPECT_NEAR(s.z, 0.5, 1e-9) << "9.5 along the view axis from an eye at z 10";
  ASSERT_TRUE(p.context->value);
  EXPECT_NEAR(*p.context->value, 2.0 * s.x + s.y - s.z, 1e-12);
  EXPECT_TRUE(tg::app::resolvePick(cam, {0, 0}, 0xFFFFFFFFu, INFINITY, table, r).background());
  EXPECT_TRUE(tg::app::resolvePick(cam, {0, 0}, firstId, 9.0, table, r).glyph);
  EXPECT_THROW(tg::app::resolvePick(cam, {0, 0}, tg::render::kContextIdBase + 1, 9.0, table, r), std::logic_error);
  EXPECT_THROW(tg::app::resolvePick(cam, {0, 0}, 0xFFFFFF00u - 1, 9.0, table, r), std::logic_error);
}
