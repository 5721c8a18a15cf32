// Tier 3: what the legend says and where it sits, through the session that
// `render` and Python draw with (app/render_session.h): the default camera
// leaves the panel free of glyphs (render/legend/legend_room.h) and is untouched
// without a legend or with the user's camera; the DEC key's words against
// the glyphs' colours; the underlay's key against its data.
#include "real_data.h"
#include "render_fixture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/render_options.h"
#include "app/render_session.h"
#include "render/context_item.h"
#include "render/legend/legend_pass.h"
#include "render/slice_plane.h"

using namespace tg;

namespace {

// A flat 14 x 14 sheet of equal glyphs in z = 0, FA about 0.5: the default
// camera looks straight down on it and fills the image's height, so the
// sheet reaches under every corner of a 4:3 image.
app::Scene sheet() {
  app::Scene s;
  std::uint32_t id = 0;
  for (int j = 0; j < 14; ++j)
    for (int i = 0; i < 14; ++i) {
      const double p[3] = {double(i), double(j), 0.0};
      const double t[9] = {1.0, 0, 0, 0, 0.4, 0, 0, 0, 0.4};
      s.field.addFull(id++, p, t);
    }
  s.field.path = "(sheet)";
  s.field.sampleSpacing = 1.0;
  return s;
}

app::RenderOptions options(bool legend, render::LegendCorner corner = render::LegendCorner::BottomRight) {
  app::RenderOptions o;
  o.width = 640;
  o.height = 480;
  o.legend.params.enabled = legend;
  o.legend.params.corner = corner;
  return o;
}

struct Shot {
  render::FrameImage img;
  render::Camera cam;
  render::LegendLayout layout;  // of the legend drawn; empty without one
};

Shot shoot(const app::RenderOptions& o, app::Scene scene) {
  app::RenderSession s(o, std::move(scene), {}, false, "test");
  const app::RenderSession::Frame f = s.frame(o);
  s.draw(f);
  Shot shot{s.readback(f, render::Channels::All), f.camera, {}};
  if (const auto* l = static_cast<const render::LegendPass*>(s.renderer().legendPass())) shot.layout = l->layout();
  return shot;
}

bool isGlyph(std::uint32_t id) { return id != 0xFFFFFFFFu && !render::isContextId(id); }

// Glyph pixels (by the id channel) whose centre lies in `r`.
std::size_t glyphPixelsIn(const render::FrameImage& img, const render::LegendRect& r) {
  std::size_t n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      n += cx > r.x0 && cx < r.x1 && cy > r.y0 && cy < r.y1 && isGlyph(img.id[std::size_t(y) * img.width + x]);
    }
  return n;
}

std::size_t glyphPixels(const render::FrameImage& img) {
  return std::size_t(std::count_if(img.id.begin(), img.id.end(), isGlyph));
}

bool sameDesc(const render::CameraDesc& a, const render::CameraDesc& b) {
  return a.eyeWC == b.eyeWC && a.lookAtWC == b.lookAtWC && a.upWC == b.upWC && a.projection == b.projection &&
         a.fovYDeg == b.fovYDeg && a.orthoHeight == b.orthoHeight;
}

bool hasLabel(const render::LegendLayout& l, const std::string& text) {
  return std::any_of(l.labels.begin(), l.labels.end(), [&](const render::LegendLabel& x) { return x.text == text; });
}

std::string g3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

// In each corner: the user's camera (the framing without a legend, given as
// --eye) puts glyphs under the panel, so the scene is a fair test; the
// default camera then leaves the panel without a glyph pixel under it, and
// the sheet keeps most of its size.
TEST(LegendRoom, DefaultCameraLeavesThePanelFreeOfGlyphs) {
  using C = render::LegendCorner;
  const Shot plain = shoot(options(false), sheet());
  const std::size_t plainPixels = glyphPixels(plain.img);
  ASSERT_GT(plainPixels, 640u * 480u / 8);
  for (const C corner : {C::BottomRight, C::BottomLeft, C::TopRight, C::TopLeft}) {
    SCOPED_TRACE(int(corner));
    app::RenderOptions given = options(true, corner);
    given.eye = plain.cam.desc.eyeWC;
    given.lookAt = plain.cam.desc.lookAtWC;
    given.up = plain.cam.desc.upWC;
    const Shot user = shoot(given, sheet());
    EXPECT_TRUE(sameDesc(user.cam.desc, plain.cam.desc));  // a given camera is not re-framed
    EXPECT_GT(glyphPixelsIn(user.img, user.layout.panel), 1000u);

    const Shot framed = shoot(options(true, corner), sheet());
    ASSERT_GT(framed.layout.panel.width(), 100.0f);
    EXPECT_EQ(glyphPixelsIn(framed.img, framed.layout.panel), 0u);
    EXPECT_GT(glyphPixels(framed.img), plainPixels / 2);
  }
}

// The scenes users saw covered: published fields and the built-in scene, at
// the default size, with the legend in its default corner.
TEST(LegendRoom, RealFieldsAndTheBuiltInSceneKeepTheirGlyphsOutOfThePanel) {
  TG_REQUIRE_REAL_DATA();
  for (const std::string& in : {std::string(), test::realData("kindlmann-dt-helix/dt-helix.nhdr"),
                               test::realData("slicer-helix-dti-masked/helix-DTI.nhdr"),
                               test::realData("slicer-helix-dti-3dmatrix/helix-DTI.nhdr"),
                               test::realData("tsv-kitten-stress/kitten-stress.vtu")}) {
    SCOPED_TRACE(in);
    app::RenderOptions o;
    o.legend.params.enabled = true;
    const Shot shot = shoot(o, app::loadScene(in, io::ReadOptions{}));
    ASSERT_GT(shot.layout.panel.width(), 100.0f);
    EXPECT_EQ(glyphPixelsIn(shot.img, shot.layout.panel), 0u);
    // Room is made by moving more than by shrinking.
    app::RenderOptions off;
    off.look.noLegend = true;
    const Shot plain = shoot(off, app::loadScene(in, io::ReadOptions{}));
    const double kept = double(glyphPixels(shot.img)) / double(glyphPixels(plain.img));
    std::printf("%s: glyph pixels under the panel %zu without room, 0 with; glyph pixels kept %.2f\n",
                in.empty() ? "built-in" : in.c_str(), glyphPixelsIn(plain.img, shot.layout.panel), kept);
    EXPECT_GT(kept, 0.5);
  }
}

// Glyph pixels in the outermost column or row on each side (left, top, right, bottom).
std::array<std::size_t, 4> edgePixels(const render::FrameImage& img) {
  const auto w = float(img.width), h = float(img.height);
  return {glyphPixelsIn(img, {0, 0, 1, h}), glyphPixelsIn(img, {0, 0, w, 1}), glyphPixelsIn(img, {w - 1, 0, w, h}),
          glyphPixelsIn(img, {0, h - 1, w, h})};
}

// Two large spheres side by side, whole in the frame without a legend: the
// room made for the panel keeps them whole, in every corner. The part of
// the way that clears the panel once pushed the far sphere over the edge.
TEST(LegendRoom, GlyphsWholeWithoutALegendStayWholeWithOne) {
  const auto pair = [] {
    app::Scene s;
    for (std::uint32_t k = 0; k < 2; ++k) {
      const double p[3] = {1000.0 * k, 0.0, 0.0}, t[9] = {10, 0, 0, 0, 10, 0, 0, 0, 10};
      s.field.addFull(k, p, t);
    }
    s.field.path = "(pair)";
    s.field.sampleSpacing = 1000.0;
    return s;
  };
  app::RenderOptions o = options(false);
  o.width = 400;
  o.height = 300;
  const Shot plain = shoot(o, pair());
  ASSERT_EQ(edgePixels(plain.img), (std::array<std::size_t, 4>{}));
  using C = render::LegendCorner;
  for (const C corner : {C::BottomRight, C::BottomLeft, C::TopRight, C::TopLeft}) {
    SCOPED_TRACE(int(corner));
    o.legend.params.enabled = true;
    o.legend.params.corner = corner;
    const Shot framed = shoot(o, pair());
    EXPECT_EQ(glyphPixelsIn(framed.img, framed.layout.panel), 0u);
    EXPECT_EQ(edgePixels(framed.img), (std::array<std::size_t, 4>{}));
  }
}

// Without a legend the frame is today's: the chosen camera and every pixel
// equal those of the same view given as flags, which nothing re-frames.
TEST(LegendRoom, WithoutALegendTheFrameIsUnchanged) {
  for (const bool builtIn : {false, true}) {
    SCOPED_TRACE(builtIn);
    app::RenderOptions o = options(false);
    const auto scene = [&] { return builtIn ? app::defaultScene() : sheet(); };
    o.look.noLegend = builtIn;  // the built-in scene's own legend, refused as --no-legend does
    const Shot off = shoot(o, scene());
    EXPECT_TRUE(off.layout.labels.empty());
    app::RenderOptions given = o;
    given.eye = off.cam.desc.eyeWC;
    given.lookAt = off.cam.desc.lookAtWC;
    given.up = off.cam.desc.upWC;
    const Shot same = shoot(given, scene());
    EXPECT_TRUE(sameDesc(off.cam.desc, same.cam.desc));
    EXPECT_EQ(off.img.rgba, same.img.rgba);
    EXPECT_EQ(off.img.id, same.img.id);
    // The legend does move it: the built-in scene's panel covered glyphs.
    app::RenderOptions on = o;
    on.look.noLegend = false;
    on.legend.params.enabled = true;
    EXPECT_FALSE(sameDesc(shoot(on, scene()).cam.desc, off.cam.desc));
  }
}

// The DEC key's words, and the colouring they describe: a glyph's albedo is
// |e1| mixed with white by 1 - FA (white at FA 0, |e1| at FA 1).
TEST(LegendWords, DecKeySaysWhatTheColourIs) {
  app::RenderOptions o = options(true);
  const Shot shot = shoot(o, sheet());
  for (const char* line : {"DEC: principal eigenvector e1", "RGB = |x|,|y|,|z| of e1", "paler as FA falls: white at 0"})
    EXPECT_TRUE(hasLabel(shot.layout, line)) << line;
  EXPECT_FALSE(hasLabel(shot.layout, "|e1| as RGB, FA 1"));
  for (const render::LegendLabel& l : shot.layout.labels) EXPECT_LE(l.text.size(), 32u) << l.text;

  // Three glyphs along x, e1 = x, at FA near 0, about 0.5 and near 1; lit
  // by ambient light alone, so the pixel is the albedo.
  const double shapes[3][2] = {{1.0, 0.98}, {1.0, 0.4}, {1.0, 0.08}};
  std::vector<float> pos, ten;
  for (int k = 0; k < 3; ++k) {
    pos.insert(pos.end(), {float(3 * k), 0.0f, 0.0f});
    ten.insert(ten.end(), {float(shapes[k][0]), 0, 0, float(shapes[k][1]), 0, float(shapes[k][1])});
  }
  const tensor::GlyphSet set = tensor::buildGlyphs(pos, ten, {});
  auto ctx = gl::createOSMesaContext();
  gl::ShaderLibrary lib;
  render::GlyphRenderer r(ctx->api(), lib);
  render::CameraDesc d;
  d.eyeWC = {3, 0, 20};
  d.lookAtWC = {3, 0, 0};
  d.projection = render::Projection::Orthographic;
  d.orthoHeight = 6;
  const render::Camera cam = render::makeCamera(d, 400, 300, glm::dvec3(-2, -2, -2), glm::dvec3(8, 2, 2));
  render::GBuffer target(ctx->api(), cam.width, cam.height);
  render::FrameParams p;
  p.scale = 0.8;
  p.light = {p.light.keyDirVC, 1.0f, 0.0f, 0.0f, 0.0f, p.light.shininess};
  r.upload(set);
  r.render(cam, p, target);
  const render::FrameImage img = r.readback(cam, target, render::Channels::Color);
  for (int k = 0; k < 3; ++k) {
    const float fa = set.glyphs[std::size_t(k)].fa;
    const int x = 50 + 150 * k;  // 50 pixels a world unit, x = 3 at the centre column 200
    const std::size_t i = 4 * (std::size_t(150) * std::size_t(img.width) + std::size_t(x));
    SCOPED_TRACE(fa);
    EXPECT_NEAR(img.rgba[i], 1.0, 0.01);           // |e1| = (1, 0, 0): red stays full
    EXPECT_NEAR(img.rgba[i + 1], 1.0 - fa, 0.01);  // green and blue: the white mixed in
    EXPECT_NEAR(img.rgba[i + 2], 1.0 - fa, 0.01);
  }
  EXPECT_LT(set.glyphs[0].fa, 0.05f);
  EXPECT_GT(set.glyphs[2].fa, 0.85f);
}

// A plane of the field's FA: the key names it, spans the plane's window
// (the 1st and 99th percentiles of the finite values, computed here from
// the volume's values), labels its ends, and draws the gray ramp; a window
// given is the key's; a hidden plane has no key.
TEST(LegendUnderlay, KeyShowsTheUnderlaysNameAndRange) {
  app::RenderOptions o = options(true);
  o.slices.underlay = "fa";
  o.slices.planes = {render::PlaneSpec{2, 10}};
  app::RenderSession s(o, app::defaultScene(), {}, true, "test");
  const auto& plane = static_cast<const render::SlicePlane&>(*s.renderer().context()[0]);
  std::vector<float> finite;
  for (const float v : plane.volume().volume().values)
    if (std::isfinite(v)) finite.push_back(v);
  std::sort(finite.begin(), finite.end());
  ASSERT_GT(finite.size(), 100u);
  const auto rank = [&](double pct) {
    return double(finite[std::size_t(std::ceil(pct / 100.0 * double(finite.size()))) - 1]);
  };
  const double lo = rank(1.0), hi = rank(99.0);
  ASSERT_LT(lo, hi);

  const auto legendOf = [&](const app::RenderOptions& opt) {
    const app::RenderSession::Frame f = s.frame(opt);
    s.draw(f);
    return std::pair(static_cast<const render::LegendPass*>(s.renderer().legendPass())->layout(),
                     s.readback(f, render::Channels::Color));
  };
  const auto [layout, img] = legendOf(o);
  ASSERT_EQ(layout.underlayBars.size(), 1u);
  EXPECT_DOUBLE_EQ(layout.underlayValues[0][0], lo);
  EXPECT_DOUBLE_EQ(layout.underlayValues[0][1], hi);
  EXPECT_TRUE(hasLabel(layout, "underlay: fa"));
  EXPECT_TRUE(hasLabel(layout, g3(lo)) && hasLabel(layout, g3(hi))) << g3(lo) << " " << g3(hi);
  // Gray from black at the low end to white at the high end, unlit.
  const render::LegendRect bar = layout.underlayBars[0];
  const auto at = [&](float x) {
    const std::size_t i = 4 * (std::size_t(0.5f * (bar.y0 + bar.y1)) * std::size_t(img.width) + std::size_t(x));
    return glm::vec3(img.rgba[i], img.rgba[i + 1], img.rgba[i + 2]);
  };
  const glm::vec3 left = at(bar.x0 + 0.5f), mid = at(0.5f * (bar.x0 + bar.x1)), right = at(bar.x1 - 0.5f);
  EXPECT_LT(left.x, 0.01f);
  EXPECT_GT(right.x, 0.99f);
  EXPECT_NEAR(mid.x, 0.5f, 0.01f);
  EXPECT_EQ(mid.x, mid.y);
  EXPECT_EQ(mid.y, mid.z);

  app::RenderOptions windowed = o;
  windowed.slices.params.window = std::pair(0.2, 0.8);
  windowed.slices.params.colormap = render::Colormap::Viridis;
  auto& item = static_cast<render::SlicePlane&>(*s.renderer().context()[0]);
  item.setParams(windowed.slices.params);
  const auto [wLayout, wImg] = legendOf(windowed);
  ASSERT_EQ(wLayout.underlayBars.size(), 1u);
  EXPECT_EQ(wLayout.underlayValues[0], glm::dvec2(0.2, 0.8));
  EXPECT_TRUE(hasLabel(wLayout, "0.2") && hasLabel(wLayout, "0.5") && hasLabel(wLayout, "0.8"));
  EXPECT_TRUE(std::any_of(wLayout.swatches.begin(), wLayout.swatches.end(), [](const render::LegendSwatch& w) {
    return w.kind == render::SwatchKind::Viridis;
  }));

  item.setVisible(false);
  const auto [hLayout, hImg] = legendOf(o);
  EXPECT_TRUE(hLayout.underlayBars.empty());
  EXPECT_FALSE(hasLabel(hLayout, "underlay: fa"));
}
