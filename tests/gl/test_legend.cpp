// Tier 3: the legend pass (render/legend/legend_pass.h) on OSMesa. Its colour bar
// against the glyphs' own colours, its text where the layout puts it, its
// scale bar against the camera, and nothing at all when it is off.
#include "render_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <glm/gtc/matrix_access.hpp>

#include "io/core/image_writer.h"
#include "render/legend_layout.h"
#include "gl/golden.h"
#include "render/legend/legend_pass.h"

using namespace tg;
using test::GlFixture;

namespace {

// Glyphs in a row along x at y = 2.5, z = 0: diag(1, a, b) in varied
// shapes, so that FA, MD, cl and cp all spread over their ranges.
tensor::GlyphSet rowOfGlyphs() {
  std::vector<float> pos, ten;
  const float shapes[][2] = {{1.0f, 1.0f},  {0.9f, 0.2f},  {0.05f, 0.05f}, {0.6f, 0.6f}, {0.3f, 0.1f},
                             {0.8f, 0.05f}, {0.15f, 0.1f}, {0.5f, 0.45f},  {0.7f, 0.4f}};
  // 1/64 puts each centre on a pixel centre under topCamera, so that even
  // the thinnest glyph (half a pixel) covers it.
  float x = -4.0f + 1.0f / 64;
  for (const auto& s : shapes) {
    pos.insert(pos.end(), {x, 2.5f + 1.0f / 64, 0.0f});
    ten.insert(ten.end(), {1.0f, 0, 0, s[0], 0, s[1]});
    x += 1.0f;
  }
  return tensor::buildGlyphs(pos, ten, {});
}

// Orthographic, looking down -z at the row: 32 pixels per world unit.
render::Camera topCamera(int w, int h) {
  render::CameraDesc d;
  d.eyeWC = {0, 0, 10};
  d.lookAtWC = {0, 0, 0};
  d.projection = render::Projection::Orthographic;
  d.orthoHeight = double(h) / 32.0;
  return render::makeCamera(d, w, h, glm::dvec3(-8, -8, -2), glm::dvec3(8, 8, 2));
}

// Albedo out unchanged: ambient 1, no other light.
render::FrameParams albedoOnly(render::ColorMode mode) {
  render::FrameParams p;
  p.scale = 0.35;
  p.color = mode;
  p.light = {p.light.keyDirVC, 1.0f, 0.0f, 0.0f, 0.0f, p.light.shininess};
  p.legend.enabled = true;
  p.legend.textScale = 1;
  return p;
}

glm::vec3 pixel(const render::FrameImage& img, int x, int y) {
  const std::size_t i = 4 * (std::size_t(y) * img.width + x);
  return {img.rgba[i], img.rgba[i + 1], img.rgba[i + 2]};
}

// The pixel a WC point projects to (row 0 at the top), unrounded.
glm::dvec2 project(const render::Camera& cam, const glm::dvec3& pWC) {
  const glm::dvec4 c = cam.projVCCC * cam.viewWCVC * glm::dvec4(pWC, 1.0);
  return {(c.x / c.w + 1.0) * 0.5 * cam.width, (1.0 - c.y / c.w) * 0.5 * cam.height};
}

// The bar's colour at argument t, between the two columns around it (the
// swatch shader evaluates each column at its centre).
glm::vec3 barAt(const render::FrameImage& img, const render::LegendSwatch& bar, double t) {
  const double u = bar.rect.x0 + (t - bar.t0) / (bar.t1 - bar.t0) * bar.rect.width() - 0.5;
  const int c0 = std::clamp(int(std::floor(u)), int(bar.rect.x0), int(bar.rect.x1) - 2);
  const auto f = float(std::clamp(u - c0, 0.0, 1.0));
  const int row = int(0.5f * (bar.rect.y0 + bar.rect.y1));
  return glm::mix(pixel(img, c0, row), pixel(img, c0 + 1, row), f);
}

const render::LegendSwatch& barOf(const render::LegendLayout& l) {
  const auto it = std::find_if(l.swatches.begin(), l.swatches.end(), [](const render::LegendSwatch& s) {
    return s.kind == render::SwatchKind::Viridis || s.kind == render::SwatchKind::Sign;
  });
  EXPECT_NE(it, l.swatches.end());
  return *it;
}

bool inside(const render::LegendRect& r, int x, int y) {
  const float px = float(x) + 0.5f, py = float(y) + 0.5f;  // the pixel's centre
  return px > r.x0 && px < r.x1 && py > r.y0 && py < r.y1;
}

// The legend's text grey (236/255 on every channel).
bool textPixel(const glm::vec3& c) {
  return std::abs(c.r - c.g) < 0.02f && std::abs(c.g - c.b) < 0.02f && c.r > 0.85f;
}

class Legend : public GlFixture {
 protected:
  struct Frame {
    render::FrameImage img;
    render::LegendLayout layout;
  };
  Frame drawWithLegend(const tensor::GlyphSet& set, const render::Camera& cam, const render::FrameParams& p) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_, render::makeLegendPass);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    r.render(cam, p, target);
    EXPECT_NE(r.legendPass(), nullptr);
    return {r.readback(cam, target, render::Channels::Color), static_cast<const render::LegendPass*>(r.legendPass())->layout()};
  }
};

}  // namespace

TEST(LegendLayout, RoundLengthsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(render::roundLengthBelow(7.3), 5.0);
  EXPECT_DOUBLE_EQ(render::roundLengthBelow(10.0), 10.0);
  EXPECT_DOUBLE_EQ(render::roundLengthBelow(0.19), 0.1);
  EXPECT_DOUBLE_EQ(render::roundLengthBelow(0.999), 0.5);
  EXPECT_DOUBLE_EQ(render::roundLengthBelow(2.5e-7), 2e-7);
  EXPECT_DOUBLE_EQ(render::roundLengthBelow(4.0e12), 2e12);
  EXPECT_EQ(render::roundLengthBelow(0.0), 0.0);
  EXPECT_EQ(render::roundLengthBelow(-1.0), 0.0);
  EXPECT_EQ(render::roundLengthBelow(INFINITY), 0.0);
  // Fills between 40% and 100% of the room it has, at any zoom.
  for (double h : {0.003, 1.0, 7.0, 4e5}) {
    render::CameraDesc d;
    d.projection = render::Projection::Orthographic;
    d.orthoHeight = h;
    const auto cam = render::makeCamera(d, 400, 300, glm::dvec3(-1), glm::dvec3(1));
    const render::ScaleBarChoice c = render::chooseScaleBar(cam, 0.5, 160);
    EXPECT_LE(c.pixels, 160.0 + 1e-9) << h;
    EXPECT_GE(c.pixels, 0.4 * 160.0) << h;
    EXPECT_DOUBLE_EQ(c.eigenvalue, c.lengthWC);  // diameter 2 * 0.5 * |l|
  }
}

// Labels of one row never overlap, whatever the md values print as; the
// middle value is left out when it would not fit.
TEST(LegendLayout, TickLabelsDoNotOverlap) {
  const render::LegendFont font(1);
  render::CameraDesc d;
  const auto cam = render::makeCamera(d, 640, 480, glm::dvec3(-1), glm::dvec3(1));
  render::LegendParams p;
  p.enabled = true;
  for (const auto& [lo, hi] : {std::pair{0.0007f, 0.000733f}, std::pair{-12345.6f, 98765.4f}, std::pair{0.0f, 1.0f}}) {
    const render::LegendInputs in{render::ColorMode::MD, 1.0, lo, hi, 0.0, 0.0};
    const render::LegendLayout l = render::layoutLegend(p, in, cam, font);
    for (std::size_t i = 0; i < l.labels.size(); ++i) {
      EXPECT_GE(l.labels[i].rect.x0, l.panel.x0);
      EXPECT_LE(l.labels[i].rect.x1, l.panel.x1);
      for (std::size_t j = i + 1; j < l.labels.size(); ++j) {
        const render::LegendRect a = l.labels[i].rect, b = l.labels[j].rect;
        const bool apart = a.x1 <= b.x0 || b.x1 <= a.x0 || a.y1 <= b.y0 || b.y1 <= a.y0;
        EXPECT_TRUE(apart) << l.labels[i].text << " / " << l.labels[j].text;
      }
    }
  }
}

// An underlay's file name as its key's title: one line however the file is
// named (a newline once put the name's tail over the bar), cut between
// UTF-8 characters when long, and every label clear of the bar.
TEST(LegendLayout, UnderlayTitleIsOneLineOfWholeCharacters) {
  const render::LegendFont font(1);
  render::CameraDesc d;
  const auto cam = render::makeCamera(d, 640, 480, glm::dvec3(-1), glm::dvec3(1));
  render::LegendParams p;
  p.enabled = true;
  for (const std::string name : {"/data/line1\nline2.nhdr", "esc\x1b[31m\tred\r.nii", "a\x7f.nrrd",
                                 "/d/Fraktionale-Anisotropie-\xc3\xa4\xc3\xb6\xc3\xbc-\xe6\x97\xa5\xe6\x9c\xac"
                                 "\xe8\xaa\x9e\xe3\x83\x86\xe3\x82\xb9\xe3\x83\x88.nhdr"}) {
    SCOPED_TRACE(name);
    render::LegendInputs in{render::ColorMode::FA, 1.0, 0, 0, 0.0, 0.0};
    in.underlays = {render::UnderlayKey{name, render::Colormap::Gray, 0.0, 1.0}};
    const render::LegendLayout l = render::layoutLegend(p, in, cam, font);
    ASSERT_EQ(l.underlayBars.size(), 1u);
    const auto title = std::find_if(l.labels.begin(), l.labels.end(), [](const render::LegendLabel& x) {
      return x.text.rfind("underlay: ", 0) == 0;
    });
    ASSERT_NE(title, l.labels.end());
    std::size_t chars = 0;
    for (std::size_t i = 0; i < title->text.size();) {
      const auto c = static_cast<unsigned char>(title->text[i]);
      EXPECT_TRUE(c >= 0x20 && c != 0x7f) << int(c);
      const std::size_t len = c < 0x80 ? 1 : c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
      ASSERT_LE(i + len, title->text.size());
      for (std::size_t k = 1; k < len; ++k) EXPECT_EQ(static_cast<unsigned char>(title->text[i + k]) & 0xC0, 0x80);
      i += len;
      ++chars;
    }
    EXPECT_LE(chars, 10u + 28u);  // "underlay: " and the name, cut
    const render::LegendRect bar = l.underlayBars[0];
    for (const render::LegendLabel& x : l.labels) {
      const render::LegendRect a = x.rect;
      const bool apart = a.x1 <= bar.x0 || bar.x1 <= a.x0 || a.y1 <= bar.y0 || bar.y1 <= a.y0;
      EXPECT_TRUE(apart) << x.text;
    }
  }
}

// A window narrower than three digits show: the bar's end labels still
// differ (1 to 1.0000001 read "1 1 1"), a usual one keeps three digits.
TEST(LegendLayout, TickLabelsTellTheEndsApart) {
  const render::LegendFont font(1);
  render::CameraDesc d;
  const auto cam = render::makeCamera(d, 640, 480, glm::dvec3(-1), glm::dvec3(1));
  render::LegendParams p;
  p.enabled = true;
  p.colorKey = false;
  for (const auto& [lo, hi] : {std::pair{1.0, double(std::nextafter(1.0f, 2.0f))}, std::pair{-3e38, 3e38 * (1 - 1e-7)},
                               std::pair{0.25, 0.75}}) {
    render::LegendInputs in{render::ColorMode::FA, 1.0, 0, 0, 0.0, 0.0};
    in.underlays = {render::UnderlayKey{"u.nrrd", render::Colormap::Gray, lo, hi}};
    const render::LegendLayout l = render::layoutLegend(p, in, cam, font);
    ASSERT_EQ(l.underlayBars.size(), 1u);
    // The labels on the row below the bar, left to right.
    float rowY = INFINITY;
    for (const render::LegendLabel& x : l.labels)
      if (x.rect.y0 >= l.underlayBars[0].y1) rowY = std::min(rowY, x.rect.y0);
    std::vector<render::LegendLabel> below;
    std::copy_if(l.labels.begin(), l.labels.end(), std::back_inserter(below),
                 [&](const render::LegendLabel& x) { return x.rect.y0 == rowY; });
    std::sort(below.begin(), below.end(), [](const auto& a, const auto& b) { return a.rect.x0 < b.rect.x0; });
    std::vector<std::string> row;
    for (const render::LegendLabel& x : below) row.push_back(x.text);
    ASSERT_GE(row.size(), 2u) << lo;
    EXPECT_NE(row.front(), row.back());
    if (lo == 0.25) {
      EXPECT_EQ(row, (std::vector<std::string>{"0.25", "0.5", "0.75"}));
    }
  }
}

// The scale bar's last line reads through the magnitude mapping: the
// eigenvalue whose glyph is the bar's length (tensor::mappedMagnitude
// inverted), what shape-only draws, and a clamp that no glyph can pass.
TEST(LegendLayout, ScaleBarReadsThroughTheMagnitudeMapping) {
  const render::LegendFont font(1);
  render::CameraDesc d;
  const auto cam = render::makeCamera(d, 640, 480, glm::dvec3(-1), glm::dvec3(1));
  render::LegendParams p;
  p.enabled = true;
  p.colorKey = false;
  auto last = [&](const tensor::SizeMapping& s, double scale) {
    const render::LegendInputs in{render::ColorMode::FA, scale, 0, 0, 0.0, 0.0, s};
    const render::LegendLayout l = render::layoutLegend(p, in, cam, font);
    EXPECT_TRUE(l.hasScaleBar);
    return std::pair{l.labels.empty() ? std::string() : l.labels.back().text, l.scale};
  };
  tensor::SizeMapping lin;
  const auto [linText, linBar] = last(lin, 0.5);
  EXPECT_NE(linText.find("eigenvalue"), std::string::npos) << linText;
  EXPECT_DOUBLE_EQ(linBar.eigenvalue, linBar.lengthWC);  // diameter 2 * 0.5 * |l|

  tensor::SizeMapping log = lin;
  log.magnitude = tensor::Magnitude::Log;
  log.lambda0 = 0.25;
  const auto [logText, logBar] = last(log, 0.5);
  // f(m) = l0 ln(1 + m / l0) is the bar's mapped size lengthWC: m = l0 (e^(f/l0) - 1).
  const double m = 0.25 * std::expm1(logBar.lengthWC / 0.25);
  char want[64];
  std::snprintf(want, sizeof want, "eigenvalue %.3g (log sizes)", m);
  EXPECT_NE(logText.find(want), std::string::npos) << logText << " / " << want;
  EXPECT_NEAR(tensor::mappedMagnitude(log, m), logBar.lengthWC, 1e-9 * logBar.lengthWC);

  tensor::SizeMapping shape = lin;
  shape.magnitude = tensor::Magnitude::Shape;
  shape.lambda0 = 2.0;
  EXPECT_NE(last(shape, 0.5).first.find("shape only: every glyph 2 world units across"), std::string::npos)
      << last(shape, 0.5).first;

  tensor::SizeMapping clamped = lin;
  clamped.maxRadiusWC = 1e-6;  // far below a pixel: the bar keeps its length and says so
  EXPECT_NE(last(clamped, 0.5).first.find("glyphs at most 2e-06 world units across"), std::string::npos)
      << last(clamped, 0.5).first;
  // Lengths are in the positions' units where the file names them, as the bar's own line.
  p.lengthUnits = "mm";
  EXPECT_NE(last(clamped, 0.5).first.find("glyphs at most 2e-06 mm across"), std::string::npos)
      << last(clamped, 0.5).first;
  EXPECT_NE(last(shape, 0.5).first.find("shape only: every glyph 2 mm across"), std::string::npos)
      << last(shape, 0.5).first;
}

// Off: no pass, no bytes, and the frame bit-identical to one that never had a
// legend. On: the legend changes pixels in its panel and nowhere else.
TEST_F(Legend, OffBuildsNothingAndLeavesTheFrameBitIdentical) {
  const auto set = rowOfGlyphs();
  const auto cam = topCamera(320, 240);
  render::FrameParams p = albedoOnly(render::ColorMode::FA);
  p.legend.enabled = false;
  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_, render::makeLegendPass);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(set);
  r.render(cam, p, target);
  EXPECT_EQ(r.legendPass(), nullptr);
  const std::size_t bytesOff = r.gpuBytes();
  const render::FrameImage off = r.readback(cam, target, render::Channels::Color);

  p.legend.enabled = true;
  r.render(cam, p, target);
  ASSERT_NE(r.legendPass(), nullptr);
  EXPECT_GT(r.gpuBytes(), bytesOff);  // the font atlas and the vertex buffer
  const render::LegendRect panel = static_cast<const render::LegendPass*>(r.legendPass())->layout().panel;
  const render::FrameImage on = r.readback(cam, target, render::Channels::Color);
  std::size_t changedInside = 0, changedOutside = 0;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      const bool changed = pixel(on, x, y) != pixel(off, x, y);
      (inside(panel, x, y) ? changedInside : changedOutside) += changed;
    }
  EXPECT_GT(double(changedInside), 0.5 * panel.width() * panel.height());
  EXPECT_EQ(changedOutside, 0u);

  p.legend.enabled = false;
  r.render(cam, p, target);
  EXPECT_EQ(r.legendPass(), nullptr);
  EXPECT_EQ(r.gpuBytes(), bytesOff);
  EXPECT_EQ(r.readback(cam, target, render::Channels::Color).rgba, off.rgba);
  EXPECT_EQ(draw(set, cam, p).rgba, off.rgba);  // a renderer that never had one
}

// Each glyph's colour (its albedo: ambient light only) is the bar's colour at
// the glyph's value of the mapped quantity, placed on the bar by the values
// its ends are labelled with, for every viridis mode. The glyph values are
// the shader's inputs: the record's FA and eigenvalues.
TEST_F(Legend, BarColoursEqualTheGlyphColours) {
  const auto set = rowOfGlyphs();
  const auto cam = topCamera(320, 240);
  for (auto mode : {render::ColorMode::FA, render::ColorMode::MD, render::ColorMode::CL, render::ColorMode::CP}) {
    SCOPED_TRACE(int(mode));
    const render::FrameParams p = albedoOnly(mode);
    const Frame f = drawWithLegend(set, cam, p);
    const render::LegendSwatch& bar = barOf(f.layout);
    ASSERT_GT(bar.rect.width(), 100.0f);
    // The end labels print the end values.
    const auto label = [&](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3g", v);
      return std::any_of(f.layout.labels.begin(), f.layout.labels.end(),
                         [&](const render::LegendLabel& l) { return l.text == buf; });
    };
    EXPECT_TRUE(label(f.layout.barValues[0]) && label(f.layout.barValues[1]));
    if (mode == render::ColorMode::MD) {
      EXPECT_NEAR(f.layout.barValues[0], set.mdMin, 1e-6);  // as uploaded to the glyph shaders (float)
      EXPECT_NEAR(f.layout.barValues[1], set.mdMax, 1e-6);
    }
    for (const tensor::GlyphRecord& g : set.glyphs) {
      const double l0 = g.eigenvalues[0], l1 = g.eigenvalues[1], l2 = g.eigenvalues[2], tr = l0 + l1 + l2;
      const double value = mode == render::ColorMode::FA   ? double(g.fa)
                           : mode == render::ColorMode::MD ? tr / 3.0
                           : mode == render::ColorMode::CL ? (l0 - l1) / tr
                                                           : 2.0 * (l1 - l2) / tr;
      const glm::dvec2 ends = f.layout.barValues;
      const double t = (value - ends[0]) / (ends[1] - ends[0]);
      const glm::dvec2 c = project(cam, {g.posWC[0], g.posWC[1], g.posWC[2]});
      ASSERT_FALSE(inside(f.layout.panel, int(c.x), int(c.y)));
      const glm::vec3 glyph = pixel(f.img, int(c.x), int(c.y));
      const glm::vec3 key = barAt(f.img, bar, std::clamp(t, 0.0, 1.0));
      // 2/255: the glyph's albedo passes through the RGBA8 G-buffer (0.5/255),
      // and viridis bends at its knots between two bar columns (< 1/255 at
      // 160 columns); a column off or a wrong range is 3/255 and more.
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(glyph[k], key[k], 2.0 / 255.0) << "t " << t << " channel " << k;
    }
  }
}

// Sign: the bar is the normal stress in the field's units, -M..M with M the
// largest |eigenvalue| (4 here), white at 0; seen from +z, each glyph's
// centre shows its zz stress, +1 and -1: the bar at +-1/4 of its half.
TEST_F(Legend, SignBarEndsAreTensionAndCompression) {
  const float pos[6] = {2, 2.5f, 0, -2, 2.5f, 0};  // tension right, compression left
  const float ten[12] = {3, 0, 0, 2, 0, 1, -4, 0, 0, -2, 0, -1};
  const auto set = tensor::buildGlyphs(pos, ten, {});
  const auto cam = topCamera(320, 240);
  render::FrameParams p = albedoOnly(render::ColorMode::Sign);
  p.legend.units = "MPa";
  const Frame f = drawWithLegend(set, cam, p);
  const render::LegendSwatch& bar = barOf(f.layout);
  EXPECT_EQ(bar.t0, -1.0f);
  EXPECT_EQ(bar.t1, 1.0f);
  EXPECT_EQ(f.layout.barValues, glm::dvec2(-4.0, 4.0));
  const glm::vec3 tension = pixel(f.img, int(project(cam, {2, 2.5, 0}).x), int(project(cam, {2, 2.5, 0}).y));
  const glm::vec3 compression = pixel(f.img, int(project(cam, {-2, 2.5, 0}).x), int(project(cam, {-2, 2.5, 0}).y));
  for (int k = 0; k < 3; ++k) {
    // The end columns sit half a column inside t = +-1: 1/(2*160) of the
    // ramp, < 1/255; the albedo adds 0.5/255.
    EXPECT_NEAR(tension[k], barAt(f.img, bar, 0.25)[k], 2.0 / 255.0);
    EXPECT_NEAR(compression[k], barAt(f.img, bar, -0.25)[k], 2.0 / 255.0);
    EXPECT_NEAR(barAt(f.img, bar, 0.0)[k], 1.0f, 2.0 / 255.0);
  }
  EXPECT_GT(tension.r, tension.b + 0.1f);
  EXPECT_GT(compression.b, compression.r + 0.1f);
  for (const char* text : {"normal stress [MPa]", "-4", "0", "4", "compression", "tension"}) {
    const bool stated = std::any_of(f.layout.labels.begin(), f.layout.labels.end(),
                                    [&](const render::LegendLabel& l) { return l.text == text; });
    EXPECT_TRUE(stated) << text;
  }
}

// Text pixels lie in the boxes the layout gives its labels: each label has
// text-grey pixels in its box, and the panel has none outside the boxes,
// the bar's frame and ticks and the scale bar. A label's text changes only
// pixels in its own box.
TEST_F(Legend, LabelTextIsDrawnWhereTheLayoutPutsIt) {
  const auto set = rowOfGlyphs();
  const auto cam = topCamera(320, 240);
  render::FrameParams p = albedoOnly(render::ColorMode::MD);
  // Anchored left: a wider title must not move the rest of the panel.
  p.legend.corner = render::LegendCorner::BottomLeft;
  const Frame f = drawWithLegend(set, cam, p);
  ASSERT_GE(f.layout.labels.size(), 5u);
  const float k = float(f.layout.textScale);
  auto grown = [](render::LegendRect r, float by) { return render::LegendRect{r.x0 - by, r.y0 - by, r.x1 + by, r.y1 + by}; };
  for (const render::LegendLabel& l : f.layout.labels) {
    std::size_t lit = 0;
    for (int y = int(l.rect.y0); y < int(l.rect.y1); ++y)
      for (int x = int(l.rect.x0); x < int(l.rect.x1); ++x) lit += textPixel(pixel(f.img, x, y));
    // ProggyClean's thinnest character ('.', '-') lights 2 pixels.
    EXPECT_GE(lit, 2 * std::count_if(l.text.begin(), l.text.end(), [](char c) { return c != ' '; })) << l.text;
  }
  std::size_t stray = 0;
  for (int y = int(f.layout.panel.y0); y < int(f.layout.panel.y1); ++y)
    for (int x = int(f.layout.panel.x0); x < int(f.layout.panel.x1); ++x) {
      bool known = inside(grown(f.layout.colorBar, 4 * k), x, y) || inside(f.layout.scaleBar, x, y);
      for (const render::LegendLabel& l : f.layout.labels) known = known || inside(l.rect, x, y);
      stray += !known && textPixel(pixel(f.img, x, y));
    }
  EXPECT_EQ(stray, 0u);

  render::FrameParams q = p;
  q.legend.units = "kPa";
  const Frame g = drawWithLegend(set, cam, q);
  ASSERT_EQ(g.layout.labels.size(), f.layout.labels.size());
  EXPECT_EQ(f.layout.labels[0].text, "MD, mean eigenvalue (viridis)");
  EXPECT_EQ(g.layout.labels[0].text, "MD, mean eigenvalue [kPa] (viridis)");
  const render::LegendRect title = g.layout.labels[0].rect;
  std::size_t changedInTitle = 0;
  for (int y = int(title.y0); y < int(title.y1); ++y)
    for (int x = int(title.x0); x < int(title.x1); ++x) changedInTitle += pixel(f.img, x, y) != pixel(g.img, x, y);
  EXPECT_GT(changedInTitle, 10u);
  // The scale bar's label also names the units ("glyph of eigenvalue ... kPa").
  std::size_t changedOutsideLabels = 0;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      bool inLabel = false;
      for (const render::LegendLabel& l : g.layout.labels) inLabel = inLabel || inside(l.rect, x, y);
      for (const render::LegendLabel& l : f.layout.labels) inLabel = inLabel || inside(l.rect, x, y);
      const bool panelEdge = inside(f.layout.panel, x, y) != inside(g.layout.panel, x, y);
      changedOutsideLabels += !inLabel && !panelEdge && inside(f.layout.panel, x, y) &&
                              pixel(f.img, x, y) != pixel(g.img, x, y) &&
                              (textPixel(pixel(f.img, x, y)) || textPixel(pixel(g.img, x, y)));
    }
  EXPECT_EQ(changedOutsideLabels, 0u);
}

// The scale bar's drawn length is its stated world length under the camera,
// measured by projecting that length at the look-at point: within 1 pixel.
TEST_F(Legend, ScaleBarSpansItsWorldLengthOnScreen) {
  const auto set = rowOfGlyphs();
  for (auto proj : {render::Projection::Orthographic, render::Projection::Perspective}) {
    SCOPED_TRACE(int(proj));
    render::CameraDesc d;
    d.eyeWC = {3, -6, 9};
    d.lookAtWC = {0.5, 1, 0};
    d.upWC = {0, 0, 1};
    d.projection = proj;
    d.fovYDeg = 40;
    d.orthoHeight = 13;
    const auto cam = render::makeCamera(d, 360, 270, glm::dvec3(-8), glm::dvec3(8));
    const Frame f = drawWithLegend(set, cam, albedoOnly(render::ColorMode::FA));
    ASSERT_TRUE(f.layout.hasScaleBar);
    const double len = f.layout.scale.lengthWC;
    const double mantissa = len / std::pow(10.0, std::floor(std::log10(len) + 1e-9));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9) << len;
    // The projection of the stated length, centred on the look-at point, along the image's x.
    const glm::dvec3 rightWC = glm::dvec3(glm::row(cam.viewWCVC, 0));
    const double expected = glm::length(project(cam, d.lookAtWC + 0.5 * len * rightWC) -
                                        project(cam, d.lookAtWC - 0.5 * len * rightWC));
    const render::LegendRect r = f.layout.scaleBar;
    const int row = int(0.5f * (r.y0 + r.y1));
    int first = -1, last = -1;
    for (int x = int(f.layout.panel.x0); x < int(f.layout.panel.x1); ++x)
      if (textPixel(pixel(f.img, x, row))) {
        if (first < 0) first = x;
        last = x;
      }
    ASSERT_GE(first, 0);
    EXPECT_NEAR(double(last - first + 1), expected, 1.0);
    // The glyph it equals: diameter 2 * scale * |l|.
    EXPECT_NEAR(f.layout.scale.eigenvalue, len / (2 * 0.35), 1e-12 * len);
  }
}

// The dec key: each point of the sphere shows |n| for its normal n in WC,
// the colour of a glyph at FA 1 whose principal direction is n, with the
// eye-facing hemisphere turned as the camera turns; each axis's mark sits
// where that axis's channel dominates.
TEST_F(Legend, DecSphereTurnsWithTheCamera) {
  const auto set = rowOfGlyphs();
  for (const glm::dvec3 eye : {glm::dvec3(0, 0, 10), glm::dvec3(8, 1, 3), glm::dvec3(-2, -7, 5)}) {
    SCOPED_TRACE(eye.x);
    render::CameraDesc d;
    d.eyeWC = eye;
    d.upWC = std::abs(eye.z) > 9 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    const auto cam = render::makeCamera(d, 320, 240, glm::dvec3(-8), glm::dvec3(8));
    const Frame f = drawWithLegend(set, cam, albedoOnly(render::ColorMode::DEC));
    ASSERT_TRUE(f.layout.hasSphere);
    ASSERT_EQ(f.layout.axes.size(), 3u);
    const render::LegendRect s = f.layout.sphere;
    const glm::dvec2 c(0.5 * (s.x0 + s.x1), 0.5 * (s.y0 + s.y1));
    const double radius = 0.5 * s.width();
    const glm::dmat3 vcFromWC(cam.viewWCVC);
    std::size_t checked = 0;
    for (int y = int(s.y0); y < int(s.y1); ++y)
      for (int x = int(s.x0); x < int(s.x1); ++x) {
        const glm::dvec2 q((x + 0.5 - c.x) / radius, (c.y - y - 0.5) / radius);
        bool nearMark = false;
        for (const render::LegendAxisMark& m : f.layout.axes)
          nearMark = nearMark || glm::distance(glm::dvec2(m.poleDC), glm::dvec2(x + 0.5, y + 0.5)) < 5.0 * f.layout.textScale;
        for (const render::LegendLabel& l : f.layout.labels) nearMark = nearMark || inside(l.rect, x, y);
        if (glm::length(q) > 0.9 || nearMark) continue;
        const glm::dvec3 nWC = glm::transpose(vcFromWC) * glm::dvec3(q, std::sqrt(1.0 - glm::dot(q, q)));
        const glm::vec3 got = pixel(f.img, x, y);
        // Float arithmetic in the shader: 1e-3 would do; a flipped axis or
        // an untransposed rotation is off by tenths.
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(got[k], std::abs(nWC[k]), 0.01) << x << " " << y;
        ++checked;
      }
    EXPECT_GT(checked, 1500u);
    for (const render::LegendAxisMark& m : f.layout.axes) {
      // Inside the pole towards the centre, clear of the mark; a pole near
      // the centre faces the eye and its mark covers it.
      const glm::vec2 cf(c);
      if (glm::length(m.poleDC - cf) < 0.6f * float(radius)) continue;
      const glm::vec2 in = cf + 0.75f * (m.poleDC - cf);
      const glm::vec3 at = pixel(f.img, int(in.x), int(in.y));
      const int a = m.axis - 'x';
      EXPECT_GT(at[a], at[(a + 1) % 3]) << m.axis;
      EXPECT_GT(at[a], at[(a + 2) % 3]) << m.axis;
    }
  }
}

// Small golden images: the fa bar, the sign bar over stress-like glyphs, and
// the dec sphere, each with its scale bar, under the default lighting.
TEST_F(Legend, GoldenImages) {
  const float pos[12] = {-3, 2.5f, 0, -1, 2.5f, 0, 1, 2.5f, 0, 3, 2.5f, 0};
  const float mixed[24] = {1, 0.3f, 0, -0.6f, 0, 0.2f, -1, 0, 0.2f, -0.4f, 0, -0.2f,
                           0.8f, 0, 0, 0.5f, 0.1f, 0.3f, 0.9f, 0, 0.4f, -0.7f, 0, -0.2f};
  const auto stress = tensor::buildGlyphs(pos, mixed, {});
  const auto row = rowOfGlyphs();
  struct Case {
    const char* name;
    render::ColorMode mode;
    const tensor::GlyphSet& set;
  };
  for (const Case& c : {Case{"legend-fa", render::ColorMode::FA, row}, Case{"legend-sign", render::ColorMode::Sign, stress},
                        Case{"legend-dec", render::ColorMode::DEC, row}}) {
    SCOPED_TRACE(c.name);
    render::CameraDesc d;
    d.eyeWC = {2, -6, 9};
    d.upWC = {0, 0, 1};
    const auto cam = render::makeCamera(d, 256, 192, glm::dvec3(-6), glm::dvec3(6));
    render::FrameParams p;
    p.scale = 0.4;
    p.color = c.mode;
    p.legend.enabled = true;
    p.legend.units = c.mode == render::ColorMode::Sign ? "MPa" : "";
    p.legend.lengthUnits = "mm";
    const render::FrameImage img = drawWithLegend(c.set, cam, p).img;
    // As the default scene's golden image (tests/cli/test_cli.cpp): max
    // 40/255 lets another llvmpipe build shade glyphs a few levels apart,
    // while a legend text or bar moved by one pixel flips pixels by 150+;
    // mean 0.6/255 keeps shading drift under a level, while a wrong colour
    // function or range moves the bar's pixels by tens.
    test::expectMatchesGolden(img, c.name, 40, 0.6);
  }
}
