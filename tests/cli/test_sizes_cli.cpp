// Issue 31's sizes: one scale for every selection of a field (the same
// tensor the same pixel size on two selections), what --scale means
// (relative alone; absolute = ParaView's ScaleFactor, the diameter), the
// sub-pixel and clamp warnings, and a stress field's defaults and info lines.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "cli_run.h"
#include "real_data.h"

namespace fs = std::filesystem;
using tg::test::CmdResult;

namespace {

fs::path dir() { return tg::test::cliDir("sizes"); }
CmdResult run(const std::string& args) { return tg::test::runBinary(args, dir()); }

fs::path pointLoad() {
  const fs::path p = dir() / "pointload.vti";
  if (!fs::exists(p)) {
    EXPECT_EQ(run("synth boussinesq --n 16 -o " + p.string()).code, 0);
  }
  return p;
}

double scaleIn(const std::string& text) {
  std::smatch m;
  const std::regex re("scale ([0-9.e+-]+) \\(");
  return std::regex_search(text, m, re) ? std::stod(m[1]) : -1.0;
}

// Pixels per glyph id of an EXR render.
std::map<std::uint32_t, int> pixelsPerGlyph(const fs::path& exr) {
  std::map<std::uint32_t, int> n;
  auto in = OIIO::ImageInput::open(exr.string());
  if (!in) {
    ADD_FAILURE() << "cannot read " << exr;
    return n;
  }
  const OIIO::ImageSpec& spec = in->spec();
  const int c = spec.channelindex("id");
  std::vector<std::uint32_t> id(std::size_t(spec.width) * std::size_t(spec.height));
  EXPECT_TRUE(in->read_image(0, 0, c, c + 1, OIIO::TypeDesc::UINT32, id.data()));
  for (std::uint32_t v : id)
    if (v != 0xffffffffu) ++n[v];
  return n;
}

// Orange-ish (tension) and blue-ish (compression) pixels of a PNG.
std::pair<int, int> signPixels(const fs::path& png) {
  auto in = OIIO::ImageInput::open(png.string());
  if (!in) return {0, 0};
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<unsigned char> px(std::size_t(spec.width) * spec.height * 4);
  in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data());
  int orange = 0, blue = 0;
  for (std::size_t i = 0; i < px.size(); i += 4) {
    orange += px[i] > px[i + 2] + 60;
    blue += px[i + 2] > px[i] + 60;
  }
  return {orange, blue};
}

}  // namespace

// The scale on two slices and on a slice cut by an ROI is the whole
// field's: the same tensors cover the same pixels. --sizes-from selection
// brings back the per-selection size (which differs, or the test shows nothing).
TEST(Sizes, TwoSelectionsOfAFieldShareOneScale) {
  const std::string in = pointLoad().string();
  // Near the load (slice 15 of 16), seen from above: glyphs tens of pixels long.
  const std::string cam = " --size 400 400 --eye 0 0 5 --look-at 0 0 -1 --up 0 1 0 --ortho 1.2 --glyph ellipsoid --verbose";
  const fs::path a = dir() / "a.exr", b = dir() / "b.exr";
  const CmdResult ra = run("render " + in + " -o " + a.string() + cam + " --slice z:15");
  const CmdResult rb = run("render " + in + " -o " + b.string() + cam + " --slice z:15 --roi -1 -1 -3 0.3 0.3 0");
  const CmdResult rc = run("render " + in + " -o " + (dir() / "c.png").string() + cam + " --slice z:3");
  ASSERT_EQ(ra.code, 0) << ra.err;
  ASSERT_EQ(rb.code, 0) << rb.err;
  ASSERT_EQ(rc.code, 0) << rc.err;
  EXPECT_GT(scaleIn(ra.err), 0.0) << ra.err;
  EXPECT_EQ(scaleIn(ra.err), scaleIn(rb.err));
  EXPECT_EQ(scaleIn(ra.err), scaleIn(rc.err));
  EXPECT_NE(ra.err.find("ranges from the whole field (4096 tensors, before --slice"), std::string::npos) << ra.err;
  // The tensors both draw (inside the ROI) cover the same pixels in both.
  const auto pa = pixelsPerGlyph(a), pb = pixelsPerGlyph(b);
  int compared = 0;
  for (const auto& [id, n] : pb) {
    const auto it = pa.find(id);
    if (it == pa.end() || n < 20) continue;
    // Whole glyphs only: a neighbour drawn in a but not in b may hide an edge.
    EXPECT_NEAR(double(it->second), double(n), 0.1 * n) << "glyph " << id;
    ++compared;
  }
  EXPECT_GT(compared, 5);
  const CmdResult own = run("info " + in + " -q --slice z:15 --roi -1 -1 -3 0.3 0.3 0 --sizes-from selection");
  const CmdResult whole = run("info " + in + " -q --slice z:15 --roi -1 -1 -3 0.3 0.3 0");
  ASSERT_EQ(own.code, 0) << own.err;
  EXPECT_NE(own.out.find("ranges from the selection"), std::string::npos) << own.out;
  EXPECT_NE(scaleIn(own.out), scaleIn(whole.out));
  EXPECT_EQ(scaleIn(whole.out), scaleIn(ra.err));
  EXPECT_EQ(run("info " + in + " --sizes-from slab").code, 2);
}

// One unit sphere (eigenvalues 1) seen orthographically, 100 pixels per
// world unit: --scale-mode absolute --scale F draws it F world units across
// (ParaView's ScaleFactor: vtkTensorGlyph's source has radius 0.5), so
// F x 100 pixels; --scale alone multiplies the automatic size.
TEST(Sizes, ScaleIsRelativeAloneAndParaViewsDiameterWhenAbsolute) {
  const fs::path in = dir() / "unit.vtk";
  std::ofstream(in) << "# vtk DataFile Version 3.0\nunit\nASCII\nDATASET POLYDATA\nPOINTS 2 float\n0 0 0 10 0 0\n"
                       "POINT_DATA 2\nTENSORS tensors float\n1 0 0 0 1 0 0 0 1\n1 0 0 0 1 0 0 0 1\n";
  auto widthPx = [&](const std::string& flags) {
    const fs::path out = dir() / "unit.exr";
    const CmdResult r = run("render " + in.string() + " -o " + out.string() +
                            " --size 200 200 --eye 0 0 10 --look-at 0 0 0 --up 0 1 0 --ortho 2 " + flags);
    EXPECT_EQ(r.code, 0) << r.err;
    const auto n = pixelsPerGlyph(out);
    const auto it = n.find(0);
    return it == n.end() ? 0.0 : 2.0 * std::sqrt(double(it->second) / 3.14159265);
  };
  EXPECT_NEAR(widthPx("--scale-mode absolute --scale 1"), 100.0, 3.0);
  EXPECT_NEAR(widthPx("--scale-mode absolute --scale 1.5"), 150.0, 3.0);
  // Automatic: the points are 10 apart (the sample spacing), so the glyph is
  // one spacing across at F = 1 (clamped at 2); --scale 0.1 is a tenth.
  EXPECT_NEAR(widthPx("--scale 0.1"), 100.0, 3.0);
  EXPECT_NEAR(widthPx("--scale 0.15"), 150.0, 3.0);
}

// Under a pixel (not only under a quarter) and a default clamp that shrinks
// more than 5% of the glyphs at the size a --scale asked for each get one
// stderr line naming the option; the defaults draw neither.
TEST(Sizes, SubPixelAndClampWarnings) {
  const std::string in = pointLoad().string();
  // The point load's singular peak pins the sign window, which render says
  // (Sizes.ASignWindowPinnedByAPeakSaysSo): a fixed one keeps that line out.
  const std::string render = "render " + in + " -o " + (dir() / "w.png").string() + " --size 96 64 --color-range -1 1";
  const CmdResult quiet = run(render + " --glyph ellipsoid");
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  // The typical glyph at the default size is about 4 pixels: a tenth is under one.
  const CmdResult small = run(render + " --scale 0.15");
  ASSERT_EQ(small.code, 0) << small.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(small.err, m, std::regex("the typical glyph is ([0-9.e+-]+) pixels across")))
      << small.err;
  EXPECT_LT(std::stod(m[1]), 1.0);
  EXPECT_GT(std::stod(m[1]), 0.25);  // the old warning's threshold: silent here
  EXPECT_NE(small.err.find("a larger --scale"), std::string::npos) << small.err;
  EXPECT_EQ(std::count(small.err.begin(), small.err.end(), '\n'), 1) << small.err;
  // --scale 4 in the spacing mode: most glyphs reach the default clamp.
  const CmdResult clamped = run(render + " --scale 4 --magnitude linear");
  ASSERT_EQ(clamped.code, 0) << clamped.err;
  ASSERT_TRUE(std::regex_search(clamped.err, m, std::regex("the default clamp \\(2 sample spacings across\\) shrinks "
                                                           "([0-9]+)% of the glyphs at this size")))
      << clamped.err;
  EXPECT_GT(std::stoi(m[1]), 5);
  EXPECT_NE(clamped.err.find("--clamp 0"), std::string::npos) << clamped.err;
  EXPECT_EQ(std::count(clamped.err.begin(), clamped.err.end(), '\n'), 1) << clamped.err;
  // Asked for, the clamp is the user's choice: no line.
  EXPECT_EQ(run(render + " --scale 4 --magnitude linear --clamp 2").err, "");
}

// Stress fields (named so, or mostly not positive definite) get the stress
// look and info's stress lines; DTI fields keep theirs; options win.
TEST(Sizes, StressDefaultsOnStressFieldsOnly) {
  const fs::path plate = dir() / "kirsch.vti";
  ASSERT_EQ(run("synth kirsch --n 48 -o " + plate.string()).code, 0);
  std::vector<std::string> stress = {pointLoad().string(), plate.string()};
  std::vector<std::string> dti;
  if (fs::is_directory(TG_REAL_DATA_DIR)) {
    stress.push_back(tg::test::realData("tsv-kitten-stress/kitten-stress.vtu"));
    dti.push_back(tg::test::realData("slicer-helix-dti-masked/helix-DTI.nhdr"));
    dti.push_back(tg::test::realData("kindlmann-dt-helix/dt-helix.nhdr"));
  }
  for (const std::string& f : stress) {
    const CmdResult r = run("info " + f + " -q");
    ASSERT_EQ(r.code, 0) << f << r.err;
    EXPECT_NE(r.out.find("\nprincipal stress 1: ["), std::string::npos) << f << r.out;
    EXPECT_NE(r.out.find("\nvon Mises: ["), std::string::npos) << f << r.out;
    EXPECT_NE(r.out.find("\nstress defaults ("), std::string::npos) << f << r.out;
    EXPECT_EQ(r.out.find("\nFA: "), std::string::npos) << f << r.out;
    EXPECT_NE(r.out.find("magnitude log"), std::string::npos) << f << r.out;
  }
  for (const std::string& f : dti) {
    const CmdResult r = run("info " + f + " -q");
    ASSERT_EQ(r.code, 0) << f << r.err;
    EXPECT_EQ(r.out.find("stress"), std::string::npos) << f << r.out;
    EXPECT_NE(r.out.find("\nFA: "), std::string::npos) << f << r.out;
    EXPECT_NE(r.out.find("magnitude linear"), std::string::npos) << f << r.out;
  }
  // The plate's analytic extremes, which the grid's samples (none on the
  // hole's edge) approach: hoop stress 3S = 300 above and below the hole,
  // -S = -100 beside it; the plane-stress zero principal value.
  const CmdResult pr = run("info " + plate.string() + " -q");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(pr.out, m, std::regex("principal stress 1: \\[([0-9.e+-]+), ([0-9.e+-]+)\\]")));
  EXPECT_GT(std::stod(m[2]), 230.0);
  EXPECT_LE(std::stod(m[2]), 300.0);
  ASSERT_TRUE(std::regex_search(pr.out, m, std::regex("principal stress 3: \\[([0-9.e+-]+), ([0-9.e+-]+)\\]")));
  EXPECT_LT(std::stod(m[1]), -50.0);
  EXPECT_GE(std::stod(m[1]), -100.0);
  EXPECT_NEAR(std::stod(m[2]), 0.0, 1e-3);
  EXPECT_NE(pr.out.find("are not positive definite"), std::string::npos) << pr.out;  // "tensors", not "stress"

  // render: the sign colour shows tension and compression; options win.
  const fs::path png = dir() / "stress.png";
  const std::string render = "render " + plate.string() + " -o " + png.string() + " --size 640 480 --verbose";
  // The sign colour saturates at the field's largest |stress|, the hoop
  // stress 3S: the plate's strongest compression, -S, is a pale third of it
  // (no pixel strongly blue), and the window -S..S shows it saturated. The
  // sign bar is blue too: glyphs only.
  const CmdResult d = run(render + " --no-legend");
  ASSERT_EQ(d.code, 0) << d.err;
  EXPECT_NE(d.err.find("stress defaults ("), std::string::npos) << d.err;
  EXPECT_NE(d.err.find("magnitude log"), std::string::npos) << d.err;
  const auto [orange, paleBlue] = signPixels(png);
  EXPECT_GT(orange, 200);
  const CmdResult w = run(render + " --no-legend --color-range -100 100");
  ASSERT_EQ(w.code, 0) << w.err;
  const auto [o1, blue] = signPixels(png);
  EXPECT_GT(blue, 20) << o1;
  EXPECT_LT(4 * paleBlue, blue) << "the default window saturates at 3S, so -S is pale";
  // The march's options follow the kind the defaults choose: a Teem user's
  // --gamma draws the plate's superquadrics, on either glyph path, and so
  // do Teem's cylinders.
  EXPECT_EQ(run(render + " --no-legend --gamma 2").code, 0);
  const CmdResult cpu = run(render + " --no-legend --pipeline cpu");
  EXPECT_EQ(cpu.code, 0) << cpu.err;
  const CmdResult box = run(render + " --no-legend --pipeline cpu --glyph cylinder");
  EXPECT_EQ(box.code, 0) << box.err;
  const CmdResult x = run(render + " --color dec --magnitude linear --no-legend");
  ASSERT_EQ(x.code, 0) << x.err;
  EXPECT_NE(x.err.find("magnitude linear"), std::string::npos) << x.err;
}

// The kitten under stress defaults: the sign window is its peak |stress|
// (1030, at the fixed nodes), so the body is drawn nearly white. The window
// stays the peak, and render says so in one line with the window that
// colours the body; that window does colour it (many times the orange and
// blue pixels), and neither it, --color vonmises nor the Kirsch plate (whose
// 3S peak is no outlier) draws the line.
TEST(Sizes, ASignWindowPinnedByAPeakSaysSo) {
  TG_REQUIRE_REAL_DATA();
  const std::string kitten = tg::test::realData("tsv-kitten-stress/kitten-stress.vtu");
  const fs::path png = dir() / "kitten.png";
  const std::string render = "render " + kitten + " -o " + png.string() + " --size 320 240";
  const CmdResult pale = run(render);
  ASSERT_EQ(pale.code, 0) << pale.err;
  std::smatch m;
  const std::regex hint("--color sign: the window is the peak \\|normal stress\\| ([0-9.e+]+), [0-9]+x the 95th "
                        "percentile ([0-9.e+]+), .*; --color-range (-[0-9.e+]+) ([0-9.e+]+) colours them.*--color "
                        "vonmises\n");
  ASSERT_TRUE(std::regex_search(pale.err, m, hint)) << pale.err;
  EXPECT_NEAR(std::stod(m[1]), 1027.14, 0.5);  // the largest |eigenvalue| (info: eigenvalue 3 down to -1027.14)
  EXPECT_LT(4.0 * std::stod(m[2]), std::stod(m[1]));
  EXPECT_EQ(std::count(pale.err.begin(), pale.err.end(), '\n'), 1) << pale.err;
  const auto [paleOrange, paleBlue] = signPixels(png);
  const CmdResult fixed = run(render + " --color-range " + m[3].str() + " " + m[4].str());
  ASSERT_EQ(fixed.code, 0) << fixed.err;
  EXPECT_EQ(fixed.err, "");
  const auto [orange, blue] = signPixels(png);
  EXPECT_GT(orange + blue, 3 * (paleOrange + paleBlue)) << paleOrange << " " << paleBlue << " / " << orange << " " << blue;
  const CmdResult vm = run(render + " --color vonmises");
  ASSERT_EQ(vm.code, 0) << vm.err;
  EXPECT_EQ(vm.err, "");
  const fs::path plate = dir() / "kirsch-hint.vti";
  ASSERT_EQ(run("synth kirsch --n 48 -o " + plate.string()).code, 0);
  const CmdResult k = run("render " + plate.string() + " -o " + png.string() + " --size 96 64");
  ASSERT_EQ(k.code, 0) << k.err;
  EXPECT_EQ(k.err.find("--color sign"), std::string::npos) << k.err;
}
