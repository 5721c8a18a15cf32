// Tracts (render/tract_item.h) in the glyphs' G-buffer: a streamline in
// front of a glyph hides it, one behind is hidden by it, where their
// surfaces are (the tube's front surface, not its axis); the tube's normal
// turns across it; the colour is the streamline's direction or the fixed one.
#include "render_fixture.h"

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "render/tract_item.h"

namespace tg::test {
namespace {

// One prolate glyph at the origin (radii 0.9, 0.5, 0.5 at scale 1).
tensor::GlyphSet oneGlyph() {
  const std::vector<float> pos = {0.0f, 0.0f, 0.0f}, ten = {0.9f, 0.0f, 0.0f, 0.5f, 0.0f, 0.5f};
  return tensor::buildGlyphs(pos, ten, {});
}

// A straight streamline along y at height z, from y = -3 to 3 in 12 steps.
struct Line {
  std::vector<float> points;
  std::vector<std::uint64_t> starts;
};
Line alongY(float z) {
  Line l;
  for (int k = 0; k <= 12; ++k) l.points.insert(l.points.end(), {0.0f, -3.0f + 0.5f * float(k), z});
  l.starts = {0, 13};
  return l;
}

class TractsGl : public GlFixture {
 protected:
  // Looking down -z at the origin from z = 8, y up.
  render::Camera camera(render::Projection proj) {
    render::CameraDesc d;
    d.eyeWC = {0.0, 0.0, 8.0};
    d.lookAtWC = {0.0, 0.0, 0.0};
    d.upWC = {0.0, 1.0, 0.0};
    d.projection = proj;
    d.orthoHeight = 8.0;
    return render::makeCamera(d, 160, 160, glm::dvec3(-3.0), glm::dvec3(3.0));
  }
  render::FrameImage frame(const std::vector<Line>& lines, const render::Camera& cam, const render::TractParams& tp) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(oneGlyph());
    for (const Line& l : lines)
      r.addContext(std::make_unique<render::TractItem>(ctx_->api(), *lib_, "tracts", l.points, l.starts, tp));
    r.render(cam, render::FrameParams{}, target);
    return r.readback(cam, target);
  }
};

std::size_t at(const render::FrameImage& f, int x, int y) { return std::size_t(y) * std::size_t(f.width) + std::size_t(x); }

TEST_F(TractsGl, InFrontHidesTheGlyphBehindIsHiddenByIt) {
  for (auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
    SCOPED_TRACE(proj == render::Projection::Perspective ? "perspective" : "orthographic");
    const render::Camera cam = camera(proj);
    render::TractParams tp;
    tp.widthWC = 0.4f;
    const int c = 80;  // the centre pixel: the glyph's top, and the line's axis
    // In front (z = 2): the centre pixel is the tract, at its front surface.
    const render::FrameImage front = frame({alongY(2.0f)}, cam, tp);
    EXPECT_EQ(front.id[at(front, c, c)], render::kContextIdBase);
    const double eyeToSurface = 8.0 - 2.0 - 0.5 * tp.widthWC;
    EXPECT_NEAR(front.depth[at(front, c, c)], eyeToSurface, 2e-3) << "the tube's front surface, not its axis";
    // Beside the line the glyph still shows.
    EXPECT_EQ(front.id[at(front, c + 15, c)], 0u);
    // Behind (z = -2): the glyph wins over its extent, the tract beyond it.
    const render::FrameImage behind = frame({alongY(-2.0f)}, cam, tp);
    EXPECT_EQ(behind.id[at(behind, c, c)], 0u);
    std::size_t tractPx = 0, glyphOverTract = 0;
    for (int y = 0; y < behind.height; ++y) {
      tractPx += behind.id[at(behind, c, y)] == render::kContextIdBase;
      glyphOverTract += behind.id[at(behind, c, y)] == 0;
    }
    EXPECT_GT(tractPx, 40u) << "the line shows above and below the glyph";
    EXPECT_GT(glyphOverTract, 10u) << "and the glyph covers it in between";
    // A tract through the glyph's middle (z = 0, thicker than the glyph is
    // deep nowhere): the glyph's front (z = 0.5) hides it.
    const render::FrameImage through = frame({alongY(0.0f)}, cam, tp);
    EXPECT_EQ(through.id[at(through, c, c)], 0u);
  }
}

TEST_F(TractsGl, NormalsTurnAcrossTheTubeAndColourIsTheDirection) {
  const render::Camera cam = camera(render::Projection::Orthographic);
  render::TractParams tp;
  tp.widthWC = 1.6f;  // 32 pixels across
  const render::FrameImage f = frame({alongY(2.0f)}, cam, tp);
  const int y = 20;  // above the glyph
  auto normal = [&](int x) {
    const std::size_t i = at(f, x, y);
    return glm::dvec3(f.normalWC[3 * i], f.normalWC[3 * i + 1], f.normalWC[3 * i + 2]);
  };
  ASSERT_EQ(f.id[at(f, 80, y)], render::kContextIdBase);
  EXPECT_GT(normal(80).z, 0.99) << "facing the eye on its axis";
  EXPECT_NEAR(normal(80).y, 0.0, 1e-3) << "never along the streamline";
  // Towards the sides it turns outwards, +x on one and -x on the other.
  EXPECT_GT(normal(93).x, 0.6);
  EXPECT_LT(normal(67).x, -0.6);
  // Depth rises from the axis to the sides, as a tube's surface does.
  EXPECT_LT(f.depth[at(f, 80, y)], f.depth[at(f, 93, y)]);
  // Along y: green by direction; a fixed colour when asked.
  const std::size_t i = at(f, 80, y);
  EXPECT_GT(f.rgba[4 * i + 1], 4.0f * std::max(f.rgba[4 * i], f.rgba[4 * i + 2]));
  tp.byDirection = false;
  tp.color = {1.0f, 0.0f, 0.0f};
  const render::FrameImage red = frame({alongY(2.0f)}, cam, tp);
  EXPECT_GT(red.rgba[4 * i], 4.0f * std::max(red.rgba[4 * i + 1], red.rgba[4 * i + 2]));
}

TEST_F(TractsGl, SeparateStreamlinesAreNotJoinedAndThinOnesKeepAPixel) {
  const render::Camera cam = camera(render::Projection::Orthographic);
  // Two streamlines in one item, x = -2 and x = 2 along y: nothing between them.
  Line two;
  for (float x : {-2.03f, 1.97f})  // not on a pixel edge
    for (int k = 0; k <= 4; ++k) two.points.insert(two.points.end(), {x, -3.0f + 1.5f * float(k), 2.0f});
  two.starts = {0, 5, 10};
  render::TractParams tp;
  tp.widthWC = 1e-4f;  // far under a pixel: drawn a pixel wide
  const render::FrameImage f = frame({two}, cam, tp);
  std::size_t between = 0, onLines = 0;
  const int y = 30;  // above the glyph
  for (int x = 0; x < f.width; ++x) {
    const bool tract = f.id[at(f, x, y)] == render::kContextIdBase;
    const double wx = (x + 0.5) / f.width * 8.0 - 4.0;
    if (std::abs(wx) < 1.5) between += tract;
    onLines += tract;
  }
  EXPECT_EQ(between, 0u) << "the end of one streamline is not joined to the start of the next";
  EXPECT_GE(onLines, 2u);
  EXPECT_LE(onLines, 6u);
  EXPECT_THROW(render::TractItem(ctx_->api(), *lib_, "bad", two.points, std::vector<std::uint64_t>{0, 11}, tp),
               std::invalid_argument);
}

}  // namespace
}  // namespace tg::test
