// --underlay and --plane through the real binary: the bad-input contract and
// an underlay file on its own grid.
#include <cmath>
#include <fstream>
#include <iterator>

#include "cli/cli_run.h"

namespace tg::test {
namespace {

// A 4x3x2 float NRRD, with or without a placement, one voxel NaN.
std::string writeUnderlay(const std::filesystem::path& dir, const std::string& name, bool placed) {
  const auto path = dir / name;
  std::ofstream out(path, std::ios::binary);
  out << "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\nencoding: raw\nendian: little\n";
  if (placed) out << "space: RAS\nspace directions: (0.5,0,0) (0,0.5,0) (0,0,1)\nspace origin: (-1,-1,-1)\n";
  else out << "spacings: 1 1 1\n";
  out << "\n";
  for (int k = 0; k < 24; ++k) {
    const float v = k == 5 ? NAN : float(k);
    out.write(reinterpret_cast<const char*>(&v), sizeof v);
  }
  return path.string();
}

TEST(SliceCli, RendersAnUnderlayFileAndRefusesBadOnesInOneLine) {
  const auto dir = cliDir("slice");
  const auto out = dir / "out.png";
  const std::string good = writeUnderlay(dir, "under.nrrd", true);
  const CmdResult ok = runBinary("render -o " + out.string() + " --size 64 48 --underlay " + good + " --plane z:1", dir);
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(out));
  expectFailsCleanly("render -o " + out.string() + " --underlay " + (dir / "missing.nrrd").string(),
                     "missing.nrrd: no such file", out, dir, 1);
  expectFailsCleanly("render -o " + out.string() + " --underlay " + writeUnderlay(dir, "unplaced.nrrd", false),
                     "unplaced.nrrd: the file does not say where its voxels lie", out, dir, 1);
  expectFailsCleanly("render -o " + out.string() + " --underlay " + good + " --plane z:2",
                     "--plane z:2: index 2 is outside 0..1 along z of the underlay's grid", out, dir, 1);
  expectFailsCleanly("render -o " + out.string() + " --underlay fa --plane q:1", "--plane", out, dir, 1);
  expectFailsCleanly("render -o " + out.string() + " --underlay-window 0 1", "needs --underlay or --plane", out, dir, 1);
  expectFailsCleanly("render -o " + out.string() + " --underlay fa --underlay-window 1 0", "LO must be below HI", out,
                     dir, 1);
  EXPECT_EQ(runBinary("render -o " + out.string() + " --underlay fa --underlay-window 1 0", dir).code, 2);
  // The planes map in single precision: a window it cannot hold drew black or at random.
  for (const char* w : {"0 1e300", "-1e39 0", "1e-300 2e-300", "1 1.000000001"}) {
    SCOPED_TRACE(w);
    const std::string cmd = "render -o " + out.string() + " --underlay fa --underlay-window " + w;
    expectFailsCleanly(cmd, "--underlay-window", out, dir, 1);
    EXPECT_EQ(runBinary(cmd, dir).code, 2);
  }
  expectFailsCleanly("render -o " + out.string() + " --underlay fa --underlay-percentiles 5 120",
                     "--underlay-percentiles must be within 0..100", out, dir, 1);
  expectFailsCleanly("render -o " + out.string() + " --underlay fa --underlay-percentiles 50 50", "LO must be below HI",
                     out, dir, 1);
  expectFailsCleanly("render -o " + out.string() + " --underlay fa --underlay-percentiles 2 98 --underlay-window 0 1",
                     "--underlay-percentiles and --underlay-window exclude each other", out, dir, 1);
  expectFailsCleanly("render -o " + out.string() + " --underlay-percentiles 2 98", "needs --underlay or --plane", out,
                     dir, 1);
  EXPECT_EQ(runBinary("render -o " + out.string() + " --underlay " + (dir / "missing.nrrd").string(), dir).code, 1);
  // A point set has no grid for its own FA.
  const auto points = dir / "points.vtk";
  ASSERT_EQ(runBinary("synth random -o " + points.string() + " --n 10", dir).code, 0);
  expectFailsCleanly("render " + points.string() + " -o " + out.string() + " --underlay fa", "point set", out, dir, 1);
}

std::string fileBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// --underlay-percentiles moves the default window: the 0th and 100th
// percentiles of the file's finite values (0..23, one NaN) are the window
// 0..23 given by hand, pixel for pixel, and not the default 1st..99th.
TEST(SliceCli, UnderlayPercentilesSetTheWindowFromTheValues) {
  const auto dir = cliDir("slice-pct");
  const std::string under = writeUnderlay(dir, "under.nrrd", true);
  const std::string base = "render --size 64 48 --underlay " + under + " --plane z:1 --eye 0 -3 6 --look-at 0 0 0 -o ";
  const auto pct = dir / "pct.png", win = dir / "win.png", def = dir / "def.png";
  ASSERT_EQ(runBinary(base + pct.string() + " --underlay-percentiles 0 100", dir).code, 0);
  ASSERT_EQ(runBinary(base + win.string() + " --underlay-window 0 23", dir).code, 0);
  ASSERT_EQ(runBinary(base + def.string() + " --underlay-window 0 46", dir).code, 0);
  EXPECT_FALSE(fileBytes(pct).empty());
  EXPECT_EQ(fileBytes(pct), fileBytes(win));
  EXPECT_NE(fileBytes(pct), fileBytes(def));
  std::filesystem::remove_all(dir);
}

// The viewer takes the same flags; its planes and `plane N` steps are checked
// before a window opens, so these need no display.
TEST(SliceCli, ViewRefusesPlanesAndPlaneStepsBeforeOpeningAWindow) {
  const auto dir = cliDir("slice-view");
  const auto script = dir / "s.txt";
  const auto none = dir / "none.png";
  std::ofstream(script) << "zoom 2\nplane 2 off\n";
  expectFailsCleanly("view --plane z:5 --script " + script.string(),
                     "s.txt:2: plane 2: the view has 1 slice plane(s)", none, dir, 1);
  std::ofstream(script) << "plane 1 index 20\n";
  expectFailsCleanly("view --plane z:5 --script " + script.string(), "s.txt:1: plane 1: index 20 is outside 0..19 along z",
                     none, dir, 1);
  std::ofstream(script) << "plane 1 off\n";
  expectFailsCleanly("view --script " + script.string(), "s.txt:1: plane 1: the view has no slice planes", none, dir, 1);
  expectFailsCleanly("view --underlay fa --plane z:20", "--plane z:20: index 20 is outside 0..19 along z", none, dir, 1);
  EXPECT_EQ(runBinary("view --underlay-window 1 0 --underlay fa", dir).code, 2);
  std::filesystem::remove_all(dir);
}

// A 4x3x2 float NRRD of ones with the given space directions and origin.
std::string writePlaced(const std::filesystem::path& dir, const std::string& name, const std::string& directions,
                        const std::string& origin) {
  const auto path = dir / name;
  std::ofstream out(path, std::ios::binary);
  out << "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\nencoding: raw\nendian: little\n"
      << "space: RAS\nspace directions: " << directions << "\nspace origin: " << origin << "\n\n";
  for (int k = 0; k < 24; ++k) {
    const float v = 1.0f;
    out.write(reinterpret_cast<const char*>(&v), sizeof v);
  }
  return path.string();
}

// Found by attacking: an underlay whose axes span no volume was drawn as a
// flat sliver, and one with 1e30-wide voxels pushed the near plane past
// every glyph (an empty image, exit 0). The first is refused; the second
// keeps the glyphs, its plane clipped to the depth range.
TEST(SliceCli, DegenerateAndHugeUnderlaysNeverHideTheGlyphs) {
  const auto dir = cliDir("slice_extreme");
  const auto out = dir / "out.png";
  expectFailsCleanly("render -o " + out.string() + " --size 64 48 --underlay " +
                         writePlaced(dir, "flat.nrrd", "(1,0,0) (0,1,0) (1,0,0)", "(0,0,0)"),
                     "flat.nrrd: the underlay's voxel axes are singular or not finite", out, dir, 1);
  std::string plain = " --size 64 48 --no-shadows --no-ao --no-legend";
  for (int j = 2; j < 48; j += 4)
    for (int i = 2; i < 64; i += 4) plain += " --pick " + std::to_string(i) + " " + std::to_string(j);
  auto glyphHits = [](const std::string& lines) {
    std::size_t n = 0;
    for (auto at = lines.find("\"hit\":\"glyph\""); at != std::string::npos;
         at = lines.find("\"hit\":\"glyph\"", at + 1))
      ++n;
    return n;
  };
  const CmdResult alone = runBinary("render -o " + (dir / "alone.png").string() + plain, dir);
  ASSERT_EQ(alone.code, 0) << alone.err;
  ASSERT_GT(glyphHits(alone.out), 10u);
  const auto huge = writePlaced(dir, "huge.nrrd", "(1e30,0,0) (0,1e30,0) (0,0,1e30)", "(-1e30,-1e30,-1e30)");
  const CmdResult r = runBinary("render -o " + out.string() + plain + " --underlay " + huge, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GT(glyphHits(r.out), glyphHits(alone.out) / 2) << "the glyphs stay in view";
  EXPECT_EQ(runBinary("render -o " + out.string() + " --underlay ''", dir).code, 2);
}

// The plane's depth is drawn moved behind the glyph layer (--plane-offset);
// a pick reports the point on the plane itself.
TEST(SliceCli, PlanePicksLieOnThePlane) {
  const auto dir = cliDir("slice_pick");
  const auto under = writePlaced(dir, "u.nrrd", "(2,0,0) (0,2,0) (0,0,2)", "(-3,-2,1.5)");
  for (const char* offset : {"0", "1"}) {
    const CmdResult r = runBinary("render -o " + (dir / "p.png").string() +
                                      " --size 64 48 --fa-min 1 --underlay " + under +
                                      " --plane z:0 --eye 1 2 30 --look-at 0 0 0 --plane-offset " + offset +
                                      " --pick 32 24",
                                  dir);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("\"hit\":\"context\""), std::string::npos) << r.out;
    // The plane z:0 lies at z = 1.5; "surface":[x,y,z]
    const auto at = r.out.find("\"surface\":[");
    ASSERT_NE(at, std::string::npos) << r.out;
    const std::string rest = r.out.substr(at + 11);
    const double z = std::stod(rest.substr(rest.rfind(',', rest.find(']')) + 1));
    EXPECT_NEAR(z, 1.5, 1e-6) << "offset " << offset << ": " << r.out;
  }
}

// An index beyond the grid is a command-line mistake, though only the file
// tells the range: exit 2, one line with the option, its value and the
// range, and no image.
TEST(SliceCli, IndicesBeyondTheGridAreUsageErrors) {
  const auto dir = cliDir("slice_range");
  const auto out = dir / "out.png";
  const std::string under = writeUnderlay(dir, "under.nrrd", true);
  const std::string helix = (dir / "helix.nrrd").string();
  ASSERT_EQ(runBinary("synth helix -o " + helix, dir).code, 0);
  const std::pair<std::string, std::string> cases[] = {
      {"render -o " + out.string() + " --slice z:400", "--slice z:400: index 400 is outside 0..19 along z of the grid of the built-in scene"},
      {"render -o " + out.string() + " --slice x:40:3", "--slice x:40:3: index 40 is outside 0..39 along x"},
      {"render -o " + out.string() + " --plane z:100", "--plane z:100: index 100 is outside 0..19 along z of the underlay's grid (fa)"},
      {"render -o " + out.string() + " --underlay " + under + " --plane y:3", "--plane y:3: index 3 is outside 0..2 along y"},
      {"view --plane z:20", "--plane z:20: index 20 is outside 0..19 along z"},
      {"view --slice y:40", "--slice y:40: index 40 is outside 0..39 along y"},
      {"info " + helix + " --slice z:999", "--slice z:999: index 999 is outside 0.."},
      {"render " + helix + " -o " + out.string() + " --slice y:999:3", "--slice y:999:3: index 999 is outside 0.."},
  };
  for (const auto& [args, what] : cases) {
    std::filesystem::remove(out);
    const CmdResult r = runBinary(args, dir);
    EXPECT_EQ(r.code, 2) << args << " -> " << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << args << " -> " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << " -> " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
  }
}

// Planes a user would not see are said so on stderr (the render still runs):
// an underlay far from the glyphs, and a slice that is all holes.
TEST(SliceCli, InvisiblePlanesAreReported) {
  const auto dir = cliDir("slice_warn");
  const auto out = dir / "out.png";
  const auto far = writePlaced(dir, "far.nrrd", "(1,0,0) (0,1,0) (0,0,1)", "(1000,1000,1000)");
  const CmdResult r = runBinary("render -o " + out.string() + " --size 64 48 --underlay " + far, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("far.nrrd: the underlay's box"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("does not overlap the glyphs'"), std::string::npos) << r.err;
  const CmdResult near = runBinary("render -o " + out.string() + " --size 64 48 --underlay fa", dir);
  EXPECT_EQ(near.code, 0) << near.err;
  EXPECT_EQ(near.err.find("does not overlap"), std::string::npos) << near.err;
  EXPECT_EQ(near.err.find("passes beside"), std::string::npos) << near.err;
  // A box around the glyphs whose planes lie at z = -50 and 50, beyond the
  // built-in scene's |z| < 15: each plane hides every glyph or none.
  const auto around = writePlaced(dir, "around.nrrd", "(100,0,0) (0,100,0) (0,0,100)", "(-200,-100,-50)");
  const CmdResult beside =
      runBinary("render -o " + out.string() + " --size 64 48 --underlay " + around + " --plane z:0 --plane z:1", dir);
  EXPECT_EQ(beside.code, 0) << beside.err;
  EXPECT_EQ(beside.err.find("does not overlap"), std::string::npos) << beside.err;
  for (const char* plane : {"plane z:0 passes beside the glyphs' box", "plane z:1 passes beside the glyphs' box"})
    EXPECT_NE(beside.err.find(plane), std::string::npos) << beside.err;
  // A plane through the glyphs is not reported.
  const CmdResult through = runBinary("render -o " + out.string() + " --size 64 48 --underlay " + around +
                                          " --plane-at 0 0 0 0 0 1",
                                      dir);
  EXPECT_EQ(through.code, 0) << through.err;
  EXPECT_EQ(through.err.find("passes beside"), std::string::npos) << through.err;
  // The built-in scene selected to slice z:2 has no tensor, so no FA, on z:5.
  const CmdResult holes =
      runBinary("render -o " + out.string() + " --size 64 48 --slice z:2 --underlay fa --plane z:5", dir);
  EXPECT_EQ(holes.code, 0) << holes.err;
  EXPECT_NE(holes.err.find("plane z:5 shows nothing: every voxel of that slice is a hole"), std::string::npos)
      << holes.err;
}

}  // namespace
}  // namespace tg::test
