// Tier 3: colour by derived scalars and per-glyph arrays, and the sign
// colour's magnitude, on OSMesa, each against a CPU evaluation of the
// formula it draws (render/color_scalar.h, shaders/lib/color.glsl). The
// light is ambient only, so that a pixel's colour is its glyph's albedo,
// which passes through the RGBA8 G-buffer: 0.5/255 of rounding.
#include "render_fixture.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <unordered_map>
#include <vector>

#include "data-synthetic/generators.h"
#include "io/core/readers.h"
#include "io/core/writers.h"
#include "real_data.h"
#include "render/color_scalar.h"
#include "render/legend_layout.h"
#include "render/legend/legend_pass.h"
#include "render/raster_glyphs.h"
#include "app/render_session.h"
#include "app/scene.h"

using namespace tg;
using test::GlFixture;

namespace {

// The maps' CPU twins: viridis's nine knots and the diverging ramp.
glm::dvec3 viridisRef(double t) {
  static const glm::dvec3 c[9] = {{0.267, 0.005, 0.329}, {0.278, 0.175, 0.483}, {0.230, 0.322, 0.546},
                                  {0.173, 0.449, 0.558}, {0.128, 0.567, 0.551}, {0.153, 0.680, 0.504},
                                  {0.362, 0.786, 0.388}, {0.678, 0.864, 0.190}, {0.993, 0.906, 0.144}};
  const double x = std::clamp(t, 0.0, 1.0) * 8.0;
  const int i = std::min(int(x), 7);
  return glm::mix(c[i], c[i + 1], x - i);
}

glm::dvec3 signRampRef(double t) {
  t = std::clamp(t, -1.0, 1.0);
  return t >= 0.0 ? glm::mix(glm::dvec3(1.0), glm::dvec3(0.90, 0.42, 0.10), t)
                  : glm::mix(glm::dvec3(1.0), glm::dvec3(0.15, 0.40, 0.90), -t);
}

glm::dvec3 mapRef(render::Colormap m, glm::dvec2 window, double v) {
  const double t = window.y > window.x ? std::clamp((v - window.x) / (window.y - window.x), 0.0, 1.0) : 0.5;
  if (m == render::Colormap::Viridis) return viridisRef(t);
  if (m == render::Colormap::Diverging) return signRampRef(2.0 * t - 1.0);
  return glm::dvec3(t);
}

render::FrameParams albedoOnly(render::ColorMode mode, double scale) {
  render::FrameParams p;
  p.scale = scale;
  p.color = mode;
  p.light = {p.light.keyDirVC, 1.0f, 0.0f, 0.0f, 0.0f, p.light.shininess};
  return p;
}

glm::dvec3 pixel(const render::FrameImage& img, std::size_t i) {
  return {img.rgba[4 * i], img.rgba[4 * i + 1], img.rgba[4 * i + 2]};
}

double maxChannelDiff(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 d = glm::abs(a - b);
  return std::max({d.x, d.y, d.z});
}

render::Camera orthoCamera(const tensor::GlyphSet& set, double scale, int w, int h) {
  render::CameraDesc d = test::oblique(set, 1.0, render::Projection::Orthographic);
  const glm::dvec3 span = set.boundsMaxWC - set.boundsMinWC;
  // The centres' box: glyphs of a concentration may reach beyond it.
  const double extent = 1.3 * std::max({span.x, span.y, span.z}) + 1e-6;
  static_cast<void>(scale);
  d.eyeWC = d.lookAtWC + 4.0 * extent * glm::normalize(d.eyeWC - d.lookAtWC);
  d.orthoHeight = 1.2 * extent;
  return test::cameraFor(set, scale, d, w, h);
}

class ColorBy : public GlFixture {
 protected:
  // Per covered pixel, its glyph's expected colour (from the record its id
  // names) against the drawn one: the largest channel difference, and how
  // many pixels were compared.
  struct Check {
    double maxDiff = 0;
    std::size_t pixels = 0;
  };
  template <class Expected>
  static Check perGlyph(const tensor::GlyphSet& set, const render::FrameImage& img, Expected expected) {
    std::unordered_map<std::uint32_t, std::size_t> byId;
    for (std::size_t i = 0; i < set.glyphs.size(); ++i) byId[set.glyphs[i].id] = i;
    Check c;
    for (std::size_t i = 0; i < img.id.size(); ++i) {
      const auto it = byId.find(img.id[i]);
      if (it == byId.end()) continue;
      c.maxDiff = std::max(c.maxDiff, maxChannelDiff(pixel(img, i), expected(it->second)));
      ++c.pixels;
    }
    return c;
  }
};

// Each derived scalar of the record's eigenvalues, computed on the CPU per
// glyph, on its map over the window the renderer reports, which is the
// scalar's range over the glyphs (symmetric about zero on the diverging
// map). 1.5/255: the albedo's rounding (0.5/255) and viridis's knots in
// float; a wrong scalar, window or map is tens of steps.
void expectScalarColours(const tensor::GlyphSet& set, const render::FrameImage& img, render::GlyphRenderer& r,
                         const render::FrameParams& p) {
  const render::ColorMode m = p.color;
  double lo = INFINITY, hi = -INFINITY;
  for (const tensor::GlyphRecord& g : set.glyphs) {
    const double l[3] = {g.eigenvalues[0], g.eigenvalues[1], g.eigenvalues[2]};
    if (std::max(std::abs(l[0]), std::abs(l[2])) == 0.0) continue;
    const double v = render::colorScalar(m, l, g.fa);
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  glm::dvec2 window = r.colorWindow(p);
  const render::Colormap map = render::resolveColormap(p);
  if (!p.colorWindow) {
    const glm::dvec2 want = map == render::Colormap::Diverging
                                ? glm::dvec2(-std::max(std::abs(lo), std::abs(hi)), std::max(std::abs(lo), std::abs(hi)))
                                : glm::dvec2(lo, hi);
    EXPECT_NEAR(window.x, want.x, 1e-6 * std::max(std::abs(lo), std::abs(hi)));
    EXPECT_NEAR(window.y, want.y, 1e-6 * std::max(std::abs(lo), std::abs(hi)));
  }
  window = glm::dvec2(glm::vec2(window));  // as the uniform holds it
  std::unordered_map<std::uint32_t, std::size_t> byId;
  const auto c = [&] {
    double maxDiff = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < set.glyphs.size(); ++i) byId[set.glyphs[i].id] = i;
    for (std::size_t i = 0; i < img.id.size(); ++i) {
      const auto it = byId.find(img.id[i]);
      if (it == byId.end()) continue;
      const tensor::GlyphRecord& g = set.glyphs[it->second];
      const double l[3] = {g.eigenvalues[0], g.eigenvalues[1], g.eigenvalues[2]};
      maxDiff = std::max(maxDiff, maxChannelDiff(pixel(img, i), mapRef(map, window, render::colorScalar(m, l, g.fa))));
      ++n;
    }
    return std::pair(maxDiff, n);
  }();
  EXPECT_GT(c.second, 1000u);
  EXPECT_LT(c.first, 1.5 / 255.0);
}

}  // namespace

// von Mises, Tresca and the principal stresses on the kitten's FEM stress
// field; pressure and trace on the point load, by glyph id.
TEST_F(ColorBy, DerivedScalarsMatchTheCpuPerGlyph) {
  TG_REQUIRE_REAL_DATA();
  const io::TensorField kitten =
      io::readTensorField(test::realData("tsv-kitten-stress/kitten-stress.vtu"), {});
  const io::TensorField load = synth::boussinesq(12, 0.3);
  for (const io::TensorField* f : {&kitten, &load}) {
    const tensor::GlyphSet set = test::glyphsOf(*f);
    const double scale = tensor::defaultScale(set, f->sampleSpacing);
    const render::Camera cam = orthoCamera(set, scale, 400, 300);
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    using M = render::ColorMode;
    for (const M m : {M::VonMises, M::Tresca, M::S1, M::S2, M::S3, M::Pressure, M::Trace, M::MD}) {
      SCOPED_TRACE(f->path + " mode " + std::to_string(int(m)));
      const render::FrameParams p = albedoOnly(m, scale);
      r.render(cam, p, target);
      expectScalarColours(set, r.readback(cam, target), r, p);
    }
    // A fixed window and another map, for a quantity and a signed one.
    render::FrameParams p = albedoOnly(M::VonMises, scale);
    p.colorWindow = glm::dvec2(0.25, 0.75) * r.colorWindow(p).y;
    p.colormap = render::Colormap::Gray;
    r.render(cam, p, target);
    expectScalarColours(set, r.readback(cam, target), r, p);
    EXPECT_EQ(r.uploadCount(), 1u);
  }
}

// An array of one value per input index, reordered to the records
// (scalarsByRecord), in a buffer of its own: each glyph shows its value on
// the map over the values' range, and neither the values, nor a new window,
// map or mode uploads the records again.
TEST_F(ColorBy, ArrayColoursByIdWithoutReuploadingTheRecords) {
  const io::TensorField f = synth::boussinesq(10, 0.3);
  const tensor::GlyphSet set = test::glyphsOf(f);
  const double scale = tensor::defaultScale(set, f.sampleSpacing);
  const render::Camera cam = orthoCamera(set, scale, 320, 240);
  std::vector<float> byInput(f.totalPoints);
  for (std::size_t i = 0; i < byInput.size(); ++i) byInput[i] = float(std::sin(0.37 * double(i)) * 50.0 + 7.0);
  for (std::size_t i = 0; i < byInput.size(); i += 7) byInput[i] = std::numeric_limits<float>::quiet_NaN();  // missing: mid grey
  const std::vector<float> byRecord = render::scalarsByRecord(set.glyphs, byInput);

  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(set);
  const auto& raster = render::asRaster(r.glyphPath());
  render::FrameParams p = albedoOnly(render::ColorMode::DEC, scale);
  r.render(cam, p, target);
  const std::size_t bytes = r.gpuBytes();
  EXPECT_THROW(r.setColorScalars(std::vector<float>(byRecord.size() + 1), "x"), std::invalid_argument);
  r.setColorScalars(byRecord, "wave");
  EXPECT_EQ(r.gpuBytes(), bytes + byRecord.size() * sizeof(float));

  p.color = render::ColorMode::Array;
  glm::dvec2 range(INFINITY, -INFINITY);
  for (std::size_t i = 0; i < byInput.size(); ++i)
    if (std::isfinite(byInput[i])) range = glm::dvec2(std::min(range.x, double(byInput[i])), std::max(range.y, double(byInput[i])));
  EXPECT_EQ(r.colorWindow(p), range);
  for (const auto& [window, map] : {std::pair(std::optional<glm::dvec2>{}, render::Colormap::Viridis),
                                    std::pair(std::optional(glm::dvec2(-10, 30)), render::Colormap::Gray),
                                    std::pair(std::optional(glm::dvec2(-40, 40)), render::Colormap::Diverging)}) {
    p.colorWindow = window;
    p.colormap = map;
    r.render(cam, p, target);
    const glm::dvec2 w = glm::dvec2(glm::vec2(r.colorWindow(p)));
    std::size_t nanPixels = 0;
    const auto c = perGlyph(set, r.readback(cam, target), [&](std::size_t k) {
      const float v = byRecord[k];
      if (std::isnan(v)) return ++nanPixels, glm::dvec3(0.5);
      return mapRef(map, w, v);
    });
    EXPECT_GT(c.pixels, 1000u);
    EXPECT_GT(nanPixels, 0u);
    EXPECT_LT(c.maxDiff, 1.5 / 255.0);
  }
  p.color = render::ColorMode::VonMises;
  p.colormap.reset();
  r.render(cam, p, target);
  EXPECT_EQ(r.uploadCount(), 1u);
  EXPECT_EQ(raster.recordBufferUploads(), 1u);
  p.color = render::ColorMode::Array;
  EXPECT_EQ(r.legendInputs(p).scalarName, "wave");
}

// Colour by array with no values set is refused, not drawn from stale memory.
TEST_F(ColorBy, ArrayWithoutValuesIsRefused) {
  const io::TensorField f = synth::boussinesq(4, 0.3);
  const tensor::GlyphSet set = test::glyphsOf(f);
  const render::Camera cam = orthoCamera(set, 0.1, 64, 64);
  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(set);
  EXPECT_THROW(r.render(cam, albedoOnly(render::ColorMode::Array, 0.1), target), std::invalid_argument);
}

// A fixed window is what the legend's bar spans and says: its ends read LO
// and HI, and it says the window is fixed.
TEST_F(ColorBy, AFixedWindowShowsOnTheLegend) {
  const io::TensorField f = synth::boussinesq(6, 0.3);
  const tensor::GlyphSet set = test::glyphsOf(f);
  const render::Camera cam = orthoCamera(set, 0.1, 320, 240);
  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_);
  r.upload(set);
  render::FrameParams p = albedoOnly(render::ColorMode::Pressure, 0.1);
  p.legend.units = "MPa";
  p.colorWindow = glm::dvec2(-2.5, 40.0);
  const render::LegendFont font(1);
  const render::LegendLayout l = render::layoutLegend(p.legend, r.legendInputs(p), cam, font);
  EXPECT_EQ(l.barValues, glm::dvec2(-2.5, 40.0));
  for (const char* text : {"pressure -trace/3 [MPa] (diverging)", "-2.5", "40", "window fixed; clamped beyond"}) {
    const bool shown = std::any_of(l.labels.begin(), l.labels.end(), [&](const auto& label) { return label.text == text; });
    EXPECT_TRUE(shown) << text;
  }
  // Automatic: the field's pressure range, symmetric about zero on the diverging map.
  p.colorWindow.reset();
  const glm::dvec2 w = render::layoutLegend(p.legend, r.legendInputs(p), cam, font).barValues;
  EXPECT_EQ(w.x, -w.y);
  EXPECT_GT(w.y, 0.0);
}

// Two slices of one field, and the whole of it, share one colour window:
// the ranges come from the whole field before the slice (app::attachWholeField).
// The point load's stress concentrates under the load, so each slice's own
// range differs from the field's.
TEST_F(ColorBy, TwoSlicesShareTheFieldsWindow) {
  const std::string path = (std::filesystem::temp_directory_path() / "tg_color_point_load.vti").string();
  io::writeVtk(synth::boussinesq(12, 0.3), path);
  std::vector<glm::dvec2> md, vm;
  for (const long long z : {-1LL, 2LL, 9LL}) {
    app::RenderOptions o;
    o.input = path;
    o.width = 64, o.height = 48;
    if (z >= 0) o.field.read.selection.slice = io::SliceSpec{2, z, 1};
    app::Scene scene = app::loadScene(o.input, o.field.read);
    app::attachWholeField(scene, o.field, o.input, o.field.read);
    app::RenderSession s(o, std::move(scene), {}, true, "test");
    render::FrameParams p;
    p.color = render::ColorMode::MD;
    md.push_back(s.renderer().colorWindow(p));
    p.color = render::ColorMode::VonMises;
    vm.push_back(s.renderer().colorWindow(p));
    if (z >= 0) {
      // The slice's own glyphs span less than the field.
      const render::ColorRanges own = render::colorRanges(std::span(s.glyphs().glyphs.data(), s.glyphs().glyphs.size()));
      EXPECT_LT(own.of[std::size_t(render::ColorMode::VonMises)].y - own.of[std::size_t(render::ColorMode::VonMises)].x,
                vm[0].y - vm[0].x);
    }
  }
  EXPECT_EQ(md[1], md[0]);
  EXPECT_EQ(md[2], md[0]);
  EXPECT_EQ(vm[1], vm[0]);
  EXPECT_EQ(vm[2], vm[0]);
  EXPECT_LT(vm[0].x, vm[0].y);
  std::filesystem::remove(path);
}
