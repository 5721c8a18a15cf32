// Tier 2: the published datasets and the selection and scaling flags,
// through the real binary.
#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "cli/cli_run.h"
#include "real_data.h"

namespace fs = std::filesystem;

namespace {

using tg::test::CmdResult;

fs::path dir() { return tg::test::cliDir("cli_data"); }

CmdResult run(const std::string& args) { return tg::test::runBinary(args, dir()); }

// The number after `label` in `text` (e.g. "12 drawn" with label " drawn").
long long countBefore(const std::string& text, const std::string& label) {
  const std::regex re("([0-9]+)" + label);
  std::smatch m;
  if (!std::regex_search(text, m, re)) return -1;
  return std::stoll(m[1]);
}

// Pixels that differ from the background colour of the top-left corner.
int glyphPixels(const fs::path& png) {
  auto in = OIIO::ImageInput::open(png.string());
  if (!in) return -1;
  const int w = in->spec().width, h = in->spec().height;
  std::vector<unsigned char> px(std::size_t(w) * h * 4);
  in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data());
  int n = 0;
  for (std::size_t i = 0; i < px.size(); i += 4)
    n += std::abs(px[i] - px[0]) + std::abs(px[i + 1] - px[1]) + std::abs(px[i + 2] - px[2]) > 24;
  return n;
}

const std::string kHelix3x3 = "slicer-helix-dti-3dmatrix/helix-DTI.nhdr";  // 64x32x16, no mask

}  // namespace

TEST(CliData, EveryPublishedDatasetLoadsAndRenders) {
  TG_REQUIRE_REAL_DATA();
  const char* files[] = {"slicer-helix-dti-masked/helix-DTI.nhdr",
                         "slicer-helix-dti-3dmatrix/helix-DTI.nhdr",
                         "kindlmann-dt-helix/dt-helix.nhdr",
                         "slicer-fiber-tensors/fiber_vtk.vtk",
                         "slicer-fiber-tensors/tractography.vtk",
                         "tsv-kitten-stress/kitten3D_HexMesh_stressField.vtk",
                         "tsv-kitten-stress/kitten-stress.vtu"};
  for (const char* f : files) {
    for (const char* glyph : {"ellipsoid", "superquadric"}) {
      const fs::path out = dir() / "real.png";
      fs::remove(out);
      const CmdResult r = run("render " + tg::test::realData(f) + " -o " + out.string() + " --size 200 150 --glyph " +
                              glyph + " --fa-min 0.05");
      ASSERT_EQ(r.code, 0) << f << ": " << r.err;
      // Glyphs are visible. The bound is low because the fibre point sets
      // (glyphs one fibre step wide) and the kitten (a few singular glyphs set
      // the scale) draw 56-150 pixels at this size; a blank frame draws 0.
      EXPECT_GT(glyphPixels(out), 40) << f << " " << glyph;
    }
  }
}

TEST(CliData, SliceStrideAndRoiSelectTheExpectedVoxels) {
  TG_REQUIRE_REAL_DATA();
  const std::string in = tg::test::realData(kHelix3x3.c_str());
  struct Case {
    std::string flags;
    long long drawn, outside;
  } cases[] = {{"", 32768, 0},
               {"--slice z:8", 64 * 32, 32768 - 64 * 32},
               {"--slice z:8:3", 3 * 64 * 32, 32768 - 3 * 64 * 32},
               {"--slice x:0", 32 * 16, 32768 - 32 * 16},
               {"--stride 2", 32 * 16 * 8, 32768 - 32 * 16 * 8},
               {"--slice z:8 --stride 4", 0, 32768},  // z = 8 is a multiple of 4: 16 x 8 voxels
               // The grid's x runs -98.4375 + 3.125 i: [-2, 7] holds i = 31, 32, 33.
               {"--roi -2 -1000 -1000 7 1000 1000", 3 * 32 * 16, 32768 - 3 * 32 * 16},
               // The stride thins within the slice only: z = 5 is no multiple of 2 (issue 32).
               {"--slice z:5 --stride 2", 32 * 16, 32768 - 32 * 16},
               // Anatomical and world slices: the grid's k runs superior, z = -93.75 + 12.5 k.
               {"--slice axial:8", 64 * 32, 32768 - 64 * 32},
               {"--slice z=6.25mm", 64 * 32, 32768 - 64 * 32},
               {"--slice z=1.5:3", 3 * 64 * 32, 32768 - 3 * 64 * 32},
               {"--slice sagittal:0", 32 * 16, 32768 - 32 * 16}};
  cases[5].drawn = 16 * 8;
  cases[5].outside = 32768 - 16 * 8;
  for (const Case& c : cases) {
    const CmdResult r = run("info " + in + " " + c.flags);
    ASSERT_EQ(r.code, 0) << c.flags << ": " << r.err;
    EXPECT_EQ(countBefore(r.out, " drawn"), c.drawn) << c.flags << "\n" << r.out;
    EXPECT_EQ(countBefore(r.out, " outside the selection"), c.outside) << c.flags;
  }
  // The glyphs are sized to the thinned spacing within the slice: 2 x 3.125 and 2 x 6.25.
  const CmdResult thinned = run("info " + in + " --slice z:5 --stride 2");
  EXPECT_NE(thinned.out.find("sample spacing: 6.25\n"), std::string::npos) << thinned.out;
}

// Units from the header (issue 32 item 9): NRRD's "space units" reach `info`
// and, unless --length-units says otherwise, the legend's scale bar.
TEST(CliData, LengthUnitsComeFromTheHeader) {
  TG_REQUIRE_REAL_DATA();
  const std::string in = tg::test::realData(kHelix3x3.c_str());
  std::ifstream src(in);
  std::stringstream text;
  text << src.rdbuf();
  std::string header = text.str();
  const std::string file = "data file: ";
  const std::size_t at = header.find(file);
  ASSERT_NE(at, std::string::npos);
  header.insert(at + file.size(), fs::path(in).parent_path().string() + "/");
  header.insert(at, "space units: \"mm\" \"mm\" \"mm\"\n");
  const fs::path withUnits = dir() / "helix-mm.nhdr";
  std::ofstream(withUnits) << header;
  EXPECT_NE(run("info " + withUnits.string()).out.find("length units: mm\n"), std::string::npos);
  EXPECT_NE(run("info " + in).out.find("length units: (none given)\n"), std::string::npos);
}

TEST(CliData, ShapeThresholdsAndEigenvalueClamp) {
  TG_REQUIRE_REAL_DATA();
  const std::string in = tg::test::realData("kindlmann-dt-helix/dt-helix.nhdr");
  const CmdResult all = run("info " + in);
  const CmdResult linear = run("info " + in + " --cl-min 0.2");
  ASSERT_EQ(all.code, 0) << all.err;
  ASSERT_EQ(linear.code, 0) << linear.err;
  const long long n = countBefore(all.out, " drawn"), nl = countBefore(linear.out, " drawn");
  EXPECT_GT(nl, 0);
  EXPECT_LT(nl, n);
  EXPECT_EQ(countBefore(linear.out, " below cl/cp"), n - nl);
  // The clamp raises the smallest eigenvalue range's floor to the clamp.
  const CmdResult clamped = run("info " + in + " --min-eigenvalue 0.45");
  ASSERT_EQ(clamped.code, 0) << clamped.err;
  EXPECT_NE(clamped.out.find("eigenvalue 3: [0.45,"), std::string::npos) << clamped.out;
}

TEST(CliData, ScaleModes) {
  TG_REQUIRE_REAL_DATA();
  // Masked helix: spacing 3.125 mm, largest eigenvalue 0.00497547.
  const std::string in = tg::test::realData("slicer-helix-dti-masked/helix-DTI.nhdr");
  auto scaleOf = [&](const std::string& flags) {
    const CmdResult r = run("render " + in + " -o " + (dir() / "s.png").string() + " --size 64 48 --verbose " + flags);
    EXPECT_EQ(r.code, 0) << r.err;
    std::smatch m;
    const std::regex re("scale ([0-9.e+-]+)");
    return std::regex_search(r.err, m, re) ? std::stod(m[1]) : -1.0;
  };
  // Alone, a factor on the automatic size; absolute, the diameter per
  // eigenvalue unit (ParaView's ScaleFactor), so the semi-axis factor is half.
  EXPECT_NEAR(scaleOf("--scale 3"), 3.0 * scaleOf(""), 1e-4 * scaleOf(""));
  EXPECT_DOUBLE_EQ(scaleOf("--scale-mode absolute --scale 500"), 250.0);
  EXPECT_NEAR(scaleOf("--scale-mode max"), 0.5 * 3.125 / 0.00497547, 0.01);
  EXPECT_NEAR(scaleOf("--scale-mode max --scale 2"), 3.125 / 0.00497547, 0.02);
  const double spacing = scaleOf("--scale-mode spacing");
  EXPECT_GT(spacing, scaleOf("--scale-mode max"));  // the 90th percentile is below the maximum
  EXPECT_NEAR(scaleOf(""), spacing, 1e-3 * spacing);
}

TEST(CliData, BadSelectionFailsBeforeRendering) {
  TG_REQUIRE_REAL_DATA();
  const std::string in = tg::test::realData(kHelix3x3.c_str());
  const fs::path out = dir() / "never.png";
  const std::string faMap = tg::test::realData("slicer-helix-dti-masked/helix-DTI-FractionalAnisotropy.nhdr");
  const std::string otherGrid = tg::test::realData("kindlmann-dt-helix/dt-helix.nhdr");
  const std::pair<std::string, std::string> cases[] = {
      {"render " + in + " -o " + out.string() + " --slice q:3", "--slice: unknown axis"},
      {"render " + in + " -o " + out.string() + " --slice z:99", "--slice z:99: index 99 is outside 0.."},
      {"render " + in + " -o " + out.string() + " --stride 0", "--stride"},
      {"render " + in + " -o " + out.string() + " --scale-mode huge", "--scale-mode"},
      {"render " + in + " -o " + out.string() + " --cl-min 2", "--cl-min"},
      {"render " + in + " -o " + out.string() + " --layout zyx", "--layout"},
      {"render " + otherGrid + " -o " + out.string() + " --mask " + faMap, "differs from the tensor grid"},
      {"render " + in + " -o " + out.string() + " --mask " + otherGrid, "a mask or underlay must have 3 axes"},
      {"render " + tg::test::realData("slicer-fiber-tensors/fiber_vtk.vtk") + " -o " + out.string() + " --slice z:1",
       "needs a grid"}};
  for (const auto& [args, what] : cases) tg::test::expectFailsCleanly(args, what, out, dir(), 1);
}

TEST(CliData, LoadingStreamsWithinTwiceTheGlyphBuffer) {
  // The loader decodes in fixed-size chunks straight into the samples, so
  // loading plus eigen-decomposition peaks at the samples (40 B per tensor)
  // plus the glyph records (48 B): under 2x the 48-byte glyph buffer, with no
  // copy of the file's data. Measured against the same command on a tiny file.
  const fs::path big = dir() / "big.nhdr", tiny = dir() / "tiny.nhdr";
  constexpr long long n = 1000000;
  ASSERT_EQ(run("synth random --n " + std::to_string(n) + " -o " + big.string()).code, 0);
  ASSERT_EQ(run("synth random --n 1000 -o " + tiny.string()).code, 0);
  auto peakMiB = [&](const fs::path& p) {
    const CmdResult r = run("info " + p.string());
    EXPECT_EQ(r.code, 0) << r.err;
    std::smatch m;
    const std::regex re("peak memory: ([0-9.]+) MiB");
    return std::regex_search(r.out, m, re) ? std::stod(m[1]) : 1e9;
  };
  const double grown = (peakMiB(big) - peakMiB(tiny)) * 1024 * 1024;
  EXPECT_LT(grown, 2.0 * 48.0 * n) << "bytes per tensor: " << grown / n;
  EXPECT_GT(grown, 48.0 * n) << "the glyph records alone take this much";
}
