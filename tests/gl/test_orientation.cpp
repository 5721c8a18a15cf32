// The orientation letters' pass (render/legend/orientation_pass.h): built only by
// frames that ask for it, drawing only where its layout puts the letters, in
// the legend's text grey on a dark backing.
#include "render_fixture.h"

#include <cmath>
#include <vector>

#include "render/legend/legend_pass.h"
#include "render/legend/orientation_pass.h"
#include "view/anatomy.h"

using namespace tg;

namespace {

bool insideAny(const render::LegendLayout& l, int x, int y) {
  const float px = float(x) + 0.5f, py = float(y) + 0.5f;
  for (const render::LegendSwatch& s : l.swatches)
    if (px > s.rect.x0 && px < s.rect.x1 && py > s.rect.y0 && py < s.rect.y1) return true;
  return false;
}

class Orientation : public test::GlFixture {};

}  // namespace

TEST_F(Orientation, LettersAreTheirOwnPassAndDrawOnlyWhereLaidOut) {
  std::vector<float> pos, ten;
  for (int k = 0; k < 25; ++k) {
    pos.insert(pos.end(), {float(k % 5) - 2.0f, float(k / 5) - 2.0f, 0.0f});
    ten.insert(ten.end(), {1.0f, 0, 0, 0.5f, 0, 0.3f});
  }
  const tensor::GlyphSet set = tensor::buildGlyphs(pos, ten, {});
  render::CameraDesc d;
  const render::ViewAxes a = *render::namedView("axial", true);
  d.eyeWC = 20.0 * a.towardEyeWC;
  d.upWC = a.upWC;
  const render::Camera cam = render::makeCamera(d, 320, 240, glm::dvec3(-3), glm::dvec3(3));
  render::FrameParams p;
  p.scale = 0.4;
  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_, render::OverlayFactories{nullptr, render::makeOrientationPass});
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(set);
  r.render(cam, p, target);
  EXPECT_EQ(r.pass("orientation"), nullptr);
  const std::size_t bytesOff = r.gpuBytes();
  const render::FrameImage off = r.readback(cam, target, render::Channels::Color);

  p.orientationLetters = true;
  r.render(cam, p, target);
  const auto* pass = static_cast<const render::OrientationPass*>(r.pass("orientation"));
  ASSERT_NE(pass, nullptr);
  EXPECT_GT(r.gpuBytes(), bytesOff);  // its font atlas
  EXPECT_EQ(pass->reads().size(), 0u);
  ASSERT_EQ(pass->writes().size(), 1u);
  const render::LegendLayout& l = pass->layout();
  ASSERT_EQ(l.labels.size(), 4u);
  EXPECT_EQ(l.labels[0].text, "R");  // radiological axial: the patient's right on the left
  EXPECT_EQ(l.labels[1].text, "L");
  EXPECT_EQ(l.labels[2].text, "A");
  EXPECT_EQ(l.labels[3].text, "P");
  const render::FrameImage on = r.readback(cam, target, render::Channels::Color);
  std::size_t inside = 0, outside = 0, bright = 0;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      const std::size_t i = 4 * (std::size_t(y) * cam.width + x);
      bool changed = false;
      for (int c = 0; c < 3; ++c) changed |= on.rgba[i + c] != off.rgba[i + c];
      (insideAny(l, x, y) ? inside : outside) += changed;
      bright += changed && on.rgba[i] > 0.8f;
    }
  EXPECT_GT(inside, 0u);
  EXPECT_GT(bright, 8u);  // the letters' ink
  EXPECT_EQ(outside, 0u);

  p.orientationLetters = false;
  r.render(cam, p, target);
  EXPECT_EQ(r.pass("orientation"), nullptr);
  EXPECT_EQ(r.gpuBytes(), bytesOff);
  EXPECT_EQ(r.passRuns("orientation"), 1u);
}

TEST_F(Orientation, LettersKeepClearOfTheLegendPanel) {
  std::vector<float> pos, ten;
  for (int k = 0; k < 9; ++k) {
    pos.insert(pos.end(), {float(k % 3) - 1.0f, float(k / 3) - 1.0f, 0.0f});
    ten.insert(ten.end(), {1.0f, 0, 0, 0.5f, 0, 0.3f});
  }
  const tensor::GlyphSet set = tensor::buildGlyphs(pos, ten, {});
  render::CameraDesc d;
  const render::ViewAxes a = *render::namedView("axial", true);
  d.eyeWC = 20.0 * a.towardEyeWC;
  d.upWC = a.upWC;
  // An image short enough that the legend's panel reaches up past the middle of the right edge.
  const render::Camera cam = render::makeCamera(d, 480, 300, glm::dvec3(-2), glm::dvec3(2));
  render::FrameParams p;
  p.scale = 0.4;
  p.orientationLetters = true;
  p.legend.enabled = true;
  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_, render::OverlayFactories{render::makeLegendPass, render::makeOrientationPass});
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(set);
  r.render(cam, p, target);
  const auto* letters = static_cast<const render::OrientationPass*>(r.pass("orientation"));
  const auto* legend = static_cast<const render::LegendPass*>(r.pass("legend"));
  ASSERT_NE(letters, nullptr);
  ASSERT_NE(legend, nullptr);
  const render::LegendRect& panel = legend->layout().panel;
  auto meets = [&](const render::LegendRect& b) {
    return b.x0 < panel.x1 && panel.x0 < b.x1 && b.y0 < panel.y1 && panel.y0 < b.y1;
  };
  const render::LegendFont font(legend->layout().textScale);
  const render::LegendLayout free = render::layoutOrientation(cam, font);
  ASSERT_TRUE(meets(free.swatches[1].rect)) << "the scene no longer tests anything";
  for (const render::LegendSwatch& s : letters->layout().swatches) EXPECT_FALSE(meets(s.rect));
}
