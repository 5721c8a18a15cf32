// Issue 31: a selection's sizes and colour windows are the whole field's,
// worked out from one read of it (app::attachWholeField): the session reads
// nothing more, and two slices of a real field, or one cut further by a
// shape filter, get the very numbers of the whole field.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/color_array.h"
#include "app/render_session.h"
#include "app/scene.h"
#include "io/core/readers.h"
#include "real_data.h"
#include "render/color_scalar.h"
#include "render/legend_layout.h"
#include "view/camera.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

// Copies of a detached NRRD's two files, removed once the whole field is
// attached: a session that read the field again would fail.
struct DisposableCopy {
  fs::path dir, header;
  DisposableCopy(const std::string& nhdr, const std::string& data, const std::string& name) {
    dir = fs::temp_directory_path() / ("tg_field_ranges_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    header = dir / fs::path(nhdr).filename();
    fs::copy_file(nhdr, header);
    fs::copy_file(data, dir / fs::path(data).filename());
  }
  void remove() const { fs::remove_all(dir); }
  ~DisposableCopy() { remove(); }
};

struct Ranges {
  int reads = 0;  // whole reads of the file after the load: its "loading" stages run to the end
  tensor::MagnitudeSample magnitudes;
  double scale = 0;
  std::vector<glm::dvec2> windows;  // per mode of kModes
  std::vector<std::string> legendText;
  std::size_t glyphs = 0;
};

const render::ColorMode kModes[] = {render::ColorMode::MD,       render::ColorMode::VonMises, render::ColorMode::Trace,
                                    render::ColorMode::Pressure, render::ColorMode::S3,       render::ColorMode::Sign,
                                    render::ColorMode::Array};

// The session `render` builds for `o`, its sizes and windows; the field's
// files are gone before the session is made.
Ranges rangesOf(app::RenderOptions o, const DisposableCopy& copy, bool countReads = true) {
  Ranges r;
  int loaded = 0;
  bool open = false;  // a read begun and not yet counted: its end may be reported twice (the poller and the finish)
  o.field.read.progress = [&](std::string_view stage, double done, double total, std::string_view) {
    if (stage != "loading" || total <= 0) return;
    if (done < total) open = true;
    else if (open) ++loaded, open = false;
  };
  app::Scene scene = app::loadScene(o.input, o.field.read);
  const int before = loaded;
  app::attachWholeField(scene, o.field, o.input, o.field.read);
  r.reads = loaded - before;
  if (countReads) {
    EXPECT_GE(before, 1) << "the load reports no finished loading stage: nothing is counted";
  }
  copy.remove();
  o.field.read.progress = {};
  app::RenderSession s(o, std::move(scene), {}, true, "test");
  r.magnitudes = s.magnitudes();
  r.glyphs = s.glyphs().glyphs.size();
  r.scale = tensor::resolveScale(app::sizingParams(o.field, s.scene()), r.magnitudes).scale;
  const render::LegendFont font(1);
  const render::Camera cam = render::makeCamera(render::fitBox(s.glyphs().boundsMinWC, s.glyphs().boundsMaxWC,
                                                               render::Projection::Perspective, 30.0, 4.0 / 3.0),
                                                o.width, o.height, s.glyphs().boundsMinWC, s.glyphs().boundsMaxWC);
  for (const render::ColorMode m : kModes) {
    if (m == render::ColorMode::Array && o.field.read.colorArray.empty()) continue;
    render::FrameParams p;
    p.color = m;
    p.legend.enabled = true;
    p.legend.scaleBar = false;  // its length follows the camera, which frames what is drawn
    r.windows.push_back(s.renderer().colorWindow(p));
    for (const render::LegendLabel& l : render::layoutLegend(p.legend, s.renderer().legendInputs(p), cam, font).labels)
      r.legendText.push_back(l.text);
  }
  return r;
}

void expectSame(const Ranges& a, const Ranges& whole, const std::string& what) {
  EXPECT_EQ(a.magnitudes.sorted, whole.magnitudes.sorted) << what;
  EXPECT_EQ(a.magnitudes.maxAbs, whole.magnitudes.maxAbs) << what;
  // The scale is the whole field's magnitudes over the drawn samples'
  // spacing: a z slice keeps the x and y spacings alone, whichever slice.
  EXPECT_DOUBLE_EQ(a.scale * whole.magnitudes.spacing, whole.scale * a.magnitudes.spacing) << what;
  ASSERT_EQ(a.windows.size(), whole.windows.size()) << what;
  for (std::size_t k = 0; k < a.windows.size(); ++k) EXPECT_EQ(a.windows[k], whole.windows[k]) << what << ", mode " << k;
  EXPECT_EQ(a.legendText, whole.legendText) << what;
}

app::RenderOptions optionsFor(const fs::path& input) {
  app::RenderOptions o;
  o.input = input.string();
  o.width = 64, o.height = 48;
  return o;
}

}  // namespace

// Kindlmann's helix: z:2 and z:5, and z:5 under --cl-min (a shape filter,
// which the colour ranges once kept and the sizes did not), each read once
// more, whole, and sized and coloured as the whole field is.
TEST(FieldRanges, SlicesTakeTheWholeFieldsSizesAndColoursFromOneRead) {
  TG_REQUIRE_REAL_DATA();
  int copies = 0;
  const auto fresh = [&] {
    return DisposableCopy(test::realData("kindlmann-dt-helix/dt-helix.nhdr"),
                          test::realData("kindlmann-dt-helix/dt-helix.raw"), "helix" + std::to_string(copies++));
  };
  app::RenderOptions o;
  const DisposableCopy w = fresh();
  const Ranges whole = rangesOf(optionsFor(w.header), w);
  EXPECT_EQ(whole.reads, 0);
  std::vector<double> scales;
  for (const long long z : {2LL, 5LL}) {
    const DisposableCopy c = fresh();
    o = optionsFor(c.header);
    o.field.read.selection.slice = io::SliceSpec{2, z, 1};
    const Ranges r = rangesOf(o, c);
    EXPECT_EQ(r.reads, 1) << "z:" << z;
    EXPECT_LT(r.glyphs, whole.glyphs);
    expectSame(r, whole, "z:" + std::to_string(z));
    scales.push_back(r.scale);
  }
  EXPECT_EQ(scales[0], scales[1]);
  const DisposableCopy c = fresh();
  o = optionsFor(c.header);
  o.field.read.selection.slice = io::SliceSpec{2, 5, 1};
  o.field.glyph.clMin = 0.3;
  const Ranges filtered = rangesOf(o, c);
  EXPECT_EQ(filtered.reads, 1);
  expectSame(filtered, whole, "z:5 --cl-min 0.3");
  // A shape filter alone leaves the whole field loaded: nothing is read again.
  const DisposableCopy d = fresh();
  o = optionsFor(d.header);
  o.field.glyph.clMin = 0.3;
  const Ranges shapeOnly = rangesOf(o, d);
  EXPECT_EQ(shapeOnly.reads, 0);
  EXPECT_LT(shapeOnly.glyphs, whole.glyphs);
  expectSame(shapeOnly, whole, "--cl-min 0.3");
}

// --color-array with a scalar volume (Slicer's FA map of its helix): two
// slices get the whole volume's window and legend, not their own, from one
// read of the volume; --color-range still fixes it.
TEST(FieldRanges, AScalarVolumesWindowIsTheWholeFields) {
  TG_REQUIRE_REAL_DATA();
  const std::string dir = test::realData("slicer-helix-dti-masked");
  const std::string fa = dir + "/helix-DTI-FractionalAnisotropy.nhdr";
  int copies = 0;
  const auto fresh = [&] {
    return DisposableCopy(dir + "/helix-DTI.nhdr", dir + "/helix-DTI.raw.gz", "slicer" + std::to_string(copies++));
  };
  const auto options = [&](const DisposableCopy& c, long long z) {
    app::RenderOptions o = optionsFor(c.header);
    o.field.read.colorArray = fa;
    if (z >= 0) o.field.read.selection.slice = io::SliceSpec{2, z, 1};
    return o;
  };
  const DisposableCopy w = fresh();
  const Ranges whole = rangesOf(options(w, -1), w, false);  // gzip reports no finished stage
  const glm::dvec2 wholeFa = whole.windows.back();
  EXPECT_LT(wholeFa.x, wholeFa.y);
  for (const long long z : {3LL, 9LL}) {
    const DisposableCopy c = fresh();
    app::RenderOptions o = options(c, z);
    const Ranges r = rangesOf(o, c, false);
    expectSame(r, whole, "z:" + std::to_string(z));
    // The slice's own FA spans less: the test would see a per-slice window.
    app::Scene own = app::loadScene(dir + "/helix-DTI.nhdr", o.field.read);
    const tensor::GlyphSet set = tensor::buildGlyphs(own.field.positions, own.field.tensors, own.field.ids);
    std::optional<io::ScalarVolume> volume;
    const auto values = app::colorArrayValues(fa, own.field, set, volume);
    ASSERT_TRUE(values);
    const glm::dvec2 slice = render::finiteRange(values->byRecord);
    EXPECT_TRUE(slice.x > wholeFa.x || slice.y < wholeFa.y) << "z:" << z;
  }
}
