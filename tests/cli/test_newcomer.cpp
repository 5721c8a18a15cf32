// What a first-time user meets: typos, help texts that must agree with what
// the binary does, and outputs a command cannot write.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>

#include "cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using tg::test::CmdResult;

fs::path dir() { return tg::test::cliDir("newcomer"); }

CmdResult run(const std::string& args) { return tg::test::runBinary(args, dir()); }

}  // namespace

TEST(Newcomer, MistypedOptionIsNamedWithTheOneMeant) {
  const fs::path out = dir() / "typo.png";
  const std::string render = "render -o " + out.string();
  const struct {
    std::string args;
    const char* said;
  } cases[] = {
      {render + " --glpyh box", "unknown option --glpyh; did you mean --glyph?"},
      {render + " --colour=fa", "unknown option --colour; did you mean --color?"},
      {render + " --fa_min 0.3", "unknown option --fa_min; did you mean --fa-min?"},
      {render + " --xyzzy", "unknown option --xyzzy; see --help"},
      {"info " + out.string() + " --strid 2", "unknown option --strid; did you mean --stride?"},
  };
  for (const auto& c : cases) {
    tg::test::expectFailsCleanly(c.args, c.said, out, dir(), 1);
    EXPECT_EQ(run(c.args).code, 2) << c.args;
  }
}

// Before, these generated the field and then failed in the writer (exit 1,
// "writeNrrd: e.nrrd: field has no grid"): a command-line mistake, known
// before any work.
TEST(Newcomer, SynthRefusesAnOutputItsKindCannotBeWrittenToBeforeGenerating) {
  const struct {
    const char* kind;
    const char* file;
    const char* said;
  } cases[] = {
      {"extremes", "e.nrrd", "extremes is a point set: write .vtk .vtu or .vtp"},
      {"random --n 10", "r.vti", "random is a point set: write .vtk .vtu .vtp or .nhdr (streamed)"},
      {"helix", "h.png", "helix is written as .vtk .vti .vtu .vtp or .nrrd"},
      {"helix", "h.nhdr", "helix is written as .vtk .vti .vtu .vtp or .nrrd"},
  };
  for (const auto& c : cases) {
    const fs::path out = dir() / c.file;
    const std::string args = std::string("synth ") + c.kind + " -o " + out.string();
    tg::test::expectFailsCleanly(args, c.said, out, dir(), 1);
    EXPECT_EQ(run(args).code, 2) << args;
  }
  const fs::path ok = dir() / "h.vti";
  fs::remove(ok);
  EXPECT_EQ(run("synth helix --n 4 -o " + ok.string()).code, 0);
  EXPECT_TRUE(fs::exists(ok));
}

// --help said the spacing mode sizes the 99th percentile glyph (and the
// occlusion radius followed it), while the code and `info` use the 90th.
TEST(Newcomer, HelpNamesThePercentileInfoReports) {
  const fs::path field = dir() / "pct.vtk";
  ASSERT_EQ(run("synth helix --n 8 -o " + field.string()).code, 0);
  const CmdResult info = run("info " + field.string());
  ASSERT_EQ(info.code, 0) << info.err;
  const std::string key = "the glyph at the ";
  const std::size_t at = info.out.find(key);
  ASSERT_NE(at, std::string::npos) << info.out;
  const std::string pct = info.out.substr(at + key.size(), info.out.find('%', at) - at - key.size());
  const CmdResult help = run("render --help");
  ASSERT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("spacing: the glyph at the " + pct + "th percentile"), std::string::npos) << pct << "\n"
                                                                                                    << help.out;
  EXPECT_NE(help.out.find("the " + pct + "th-percentile glyph's"), std::string::npos) << pct << "\n" << help.out;
  EXPECT_EQ(help.out.find("99th"), std::string::npos);
}

// Teem's `tend glyph -g s -gsc 3` habit: --gamma with a file draws the
// default ellipsoids, on which the march's parameters have no effect. They
// were ignored in silence; now refused as --lambda0 is without --magnitude.
TEST(Newcomer, MarchOptionsOnGlyphsThatDoNotMarchAreRefused) {
  const fs::path field = dir() / "march.vtk", out = dir() / "march.png";
  ASSERT_EQ(run("synth helix --n 6 -o " + field.string()).code, 0);
  const std::string render = "render " + field.string() + " -o " + out.string() + " --size 64 48";
  const struct {
    std::string flags;
    const char* said;
  } refused[] = {
      {" --gamma 3", "--gamma applies to --glyph superquadric and blob only; this render draws ellipsoid glyphs"},
      {" --glyph box --iterations 4", "--iterations applies to --glyph superquadric only; this render draws box glyphs"},
      {" --epsilon 1e-3 --glyph cylinder", "--epsilon applies to --glyph superquadric only"},
      {" --glyph ellipsoid --gamma 1", "--gamma applies to --glyph superquadric and blob only"},
      {" --glyph blob --iterations 4", "--iterations applies to --glyph superquadric only; this render draws blob glyphs"},
      {" --blobbiness -1 --glyph box", "--blobbiness applies to --glyph blob only; this render draws box glyphs"},
      {" --blob-threshold 2", "--blob-threshold applies to --glyph blob only; this render draws ellipsoid glyphs"},
      {" --glyph blob --pipeline raster",
       "--pipeline raster draws ellipsoid, superquadric, cylinder and box glyphs only; this render draws blob glyphs "
       "(each blob pixel needs every bump its ray meets): use --pipeline cpu, or leave --pipeline out"},
      {" --glyph blob --blobbiness -0.01 --blob-cutoff 1e-9",
       "--blobbiness -0.01 with --blob-cutoff 1e-09 and --blob-threshold 1: each bump would reach 45.5338 glyph radii (at most 8)"},
      {" --glyph blob --blobbiness -0.01 --blob-cutoff 0.5 --blob-threshold 3",
       "--blob-cutoff 0.5 x --blob-threshold 3 lies above a bump's peak exp(-B) = 1.01005"},
  };
  for (const auto& c : refused) {
    tg::test::expectFailsCleanly(render + c.flags, c.said, out, dir(), 1);
    EXPECT_EQ(run(render + c.flags).code, 2) << c.flags;
  }
  // Where they apply: superquadrics, blobs (on the cpu path, which --glyph blob takes), and the built-in scene's default glyph.
  EXPECT_EQ(run(render + " --glyph superquadric --gamma 2 --iterations 6").code, 0);
  EXPECT_EQ(run(render + " --glyph blob --gamma 2 --blobbiness -1 --blob-threshold 0.8 --blob-steps 2").code, 0);
  EXPECT_EQ(run(render + " --glyph blob --pipeline cpu --shadows").code, 0);
  // A threshold no lone bump reaches draws, and says why the image may be empty.
  const tg::test::CmdResult high = run(render + " --glyph blob --blob-threshold 10");
  EXPECT_EQ(high.code, 0) << high.err;
  EXPECT_NE(high.err.find("--blob-threshold 10 is at or above a lone bump's peak exp(-B) = 7.38906"), std::string::npos)
      << high.err;
  EXPECT_EQ(run("render -o " + out.string() + " --size 64 48 --gamma 1.5 --no-shadows --no-ao").code, 0);
}

// --mask and --underlay read scalar volumes through the same readers
// (readScalarVolume); --mask's help left out MRtrix's .mif and .mih, which
// it reads (Mif.MaskSelects).
TEST(Newcomer, MaskHelpListsTheVolumeFormatsTheUnderlayHelpDoes) {
  const CmdResult help = run("render --help");
  ASSERT_EQ(help.code, 0);
  auto extensions = [&](const std::string& flag) {
    const std::size_t at = help.out.find("\n  " + flag);
    EXPECT_NE(at, std::string::npos) << flag;
    const std::string line = help.out.substr(at + 1, help.out.find('\n', at + 1) - at - 1);
    std::set<std::string> exts;
    std::istringstream words(line);
    for (std::string w; words >> w;) {
      while (!w.empty() && (w.front() == '(' || w.back() == ')' || w.back() == ',' || w.back() == ';'))
        w = w.front() == '(' ? w.substr(1) : w.substr(0, w.size() - 1);
      if (w.size() > 1 && w[0] == '.') exts.insert(w);
    }
    return exts;
  };
  const std::set<std::string> mask = extensions("--mask FILE"), underlay = extensions("--underlay SOURCE");
  EXPECT_GE(underlay.size(), 7u);
  EXPECT_EQ(mask, underlay);
}

// The cut-off legend's warning told every user to try --legend-text-scale 1,
// which is what an image under 700 rows already uses: advice that changes
// nothing. It is given only where the text is larger.
TEST(Newcomer, CutOffLegendAdvisesSmallerTextOnlyWhereItIsLarger) {
  const fs::path out = dir() / "legend.png";
  const std::string render = "render -o " + out.string() + " --no-shadows --no-ao --legend";
  const CmdResult small = run(render + " --size 200 150");
  ASSERT_EQ(small.code, 0) << small.err;
  EXPECT_NE(small.err.find("is cut off by the 200 x 150 image; use a larger --size\n"), std::string::npos) << small.err;
  EXPECT_EQ(small.err.find("--legend-text-scale"), std::string::npos) << small.err;
  const CmdResult large = run(render + " --size 400 300 --legend-text-scale 3");
  ASSERT_EQ(large.code, 0) << large.err;
  EXPECT_NE(large.err.find("use a larger --size, or --legend-text-scale 1"), std::string::npos) << large.err;
}

// --fov 0 said "camera vectors must be finite": the framed eye's distance
// divides by tan(fov / 2) before the camera's own check names --fov.
TEST(Newcomer, FieldOfViewOutOfRangeIsNamed) {
  const fs::path field = dir() / "fov.vtk", out = dir() / "fov.png";
  ASSERT_EQ(run("synth helix --n 6 -o " + field.string()).code, 0);
  for (const char* fov : {"0", "-10", "180"}) {
    const std::string args = "render " + field.string() + " -o " + out.string() + " --size 64 48 --fov " + fov;
    tg::test::expectFailsCleanly(args, "--fov must be within 0.01..179", out, dir(), 1);
    EXPECT_EQ(run(args).code, 2) << args;
  }
}

// `bench accuracy --scale-mode absolute --scale 4` (2 world units per
// eigenvalue unit: the helix's glyphs a few thousandths wide) compared frames
// without a glyph pixel and reported 0% error on every row.
TEST(Newcomer, AccuracyBenchWithNothingToCompareFails) {
  const fs::path csv = dir() / "acc.csv";
  const std::string args =
      "bench accuracy -o " + csv.string() + " --scale-mode absolute --scale 4 --size 64 48 --frames 1 --iterations 1 --epsilon 1e-2";
  tg::test::expectFailsCleanly(args, "no glyph covers a pixel at this scale and size", csv, dir(), 1);
  EXPECT_EQ(run(args).code, 1);
  EXPECT_FALSE(fs::exists(dir() / "acc.png"));
}

// An absolute scale of 1 (semi-axis) on a DTI field: its glyphs (eigenvalues
// about 0.005) come out a hundredth of a pixel wide, and render wrote an
// empty image without a word.
TEST(Newcomer, ScaleThatLeavesTheImageEmptySaysSo) {
  const fs::path field = dir() / "tiny.vtk", out = dir() / "tiny.png";
  ASSERT_EQ(run("synth helix --n 8 -o " + field.string()).code, 0);  // eigenvalues about 1e-3
  const std::string render = "render " + field.string() + " -o " + out.string() + " --size 96 64";
  const CmdResult tiny = run(render + " --scale-mode absolute --scale 2");
  ASSERT_EQ(tiny.code, 0) << tiny.err;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_NE(tiny.err.find("pixels across, so the image shows almost nothing; a larger --scale draws them"),
            std::string::npos) << tiny.err;
  EXPECT_EQ(std::count(tiny.err.begin(), tiny.err.end(), '\n'), 1) << tiny.err;
  const CmdResult framed = run(render);
  ASSERT_EQ(framed.code, 0) << framed.err;
  EXPECT_EQ(framed.err, "");
}

// --cl-min drops glyphs after the eigensystems, past checkLoaded's count: a
// threshold above every tensor's cl failed as "the glyphs extend beyond the
// floating-point range".
TEST(Newcomer, ShapeThresholdThatLeavesNothingSaysSo) {
  const fs::path field = dir() / "shape.vtk", out = dir() / "shape.png";
  ASSERT_EQ(run("synth helix --n 6 -o " + field.string()).code, 0);
  const std::string args = "render " + field.string() + " -o " + out.string() + " --size 64 48 --cl-min 1";
  tg::test::expectFailsCleanly(args, ": no tensor to draw: all ", out, dir(), 1);
  const CmdResult r = run(args);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(" are below --cl-min or --cp-min"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("floating-point range"), std::string::npos) << r.err;
}

// --fa-min above every glyph's FA (Kindlmann's helix peaks at 0.62), or a
// camera looking away, wrote a blank image without a word.
TEST(Newcomer, FrameWithoutAGlyphSaysWhy) {
  const fs::path field = dir() / "blank.vtk", out = dir() / "blank.png";
  ASSERT_EQ(run("synth helix --n 6 -o " + field.string()).code, 0);
  const std::string render = "render " + field.string() + " -o " + out.string() + " --size 64 48";
  const CmdResult hidden = run(render + " --fa-min 0.99");
  ASSERT_EQ(hidden.code, 0) << hidden.err;
  EXPECT_NE(hidden.err.find("no glyph is drawn: all "), std::string::npos) << hidden.err;
  EXPECT_NE(hidden.err.find(" are below --fa-min 0.99 or outside the view\n"), std::string::npos) << hidden.err;
  const CmdResult away = run(render + " --eye 0 0 100 --look-at 0 0 200");
  ASSERT_EQ(away.code, 0) << away.err;
  EXPECT_NE(away.err.find(" are outside the view that --eye --look-at set\n"), std::string::npos) << away.err;
  const CmdResult seen = run(render);
  ASSERT_EQ(seen.code, 0) << seen.err;
  EXPECT_EQ(seen.err, "");
}

// A mesh name whose extension no reader takes, or --mesh-from-input on a
// volume format, is known from the command line: exit 2 before the tensors
// load, where it was exit 1 after (readMesh).
TEST(Newcomer, MeshNamesNoReaderTakesAreUsageErrors) {
  const fs::path field = dir() / "meshless.vtk", nrrd = dir() / "meshless.nrrd", out = dir() / "meshless.png";
  ASSERT_EQ(run("synth helix --n 6 -o " + field.string()).code, 0);
  ASSERT_EQ(run("synth helix --n 6 -o " + nrrd.string()).code, 0);
  std::ofstream(dir() / "box.off") << "OFF\n";
  const struct {
    std::string args;
    const char* said;
  } cases[] = {
      {"render " + field.string() + " --mesh " + (dir() / "box.off").string(),
       ": unknown mesh extension \".off\"; supported: .vtk .vtp .stl .obj .ply, and .vtu .vts (outer surface)"},
      {"render " + nrrd.string() + " --mesh-from-input",
       "--mesh-from-input needs an FEM mesh input (an unstructured grid: .vtk or .vtu), not \".nrrd\""},
  };
  for (const auto& c : cases) {
    const std::string args = c.args + " -o " + out.string() + " --size 64 48";
    tg::test::expectFailsCleanly(args, c.said, out, dir(), 1);
    EXPECT_EQ(run(args).code, 2) << args;
  }
}

// --no-outlines' help said "the built-in scene without its outlines", but
// that scene has none: the flag changes nothing, and its help says so.
TEST(Newcomer, NoOutlinesHelpSaysItIsTheDefault) {
  const CmdResult help = run("render --help");
  ASSERT_EQ(help.code, 0);
  const std::size_t at = help.out.find("\n  --no-outlines");
  ASSERT_NE(at, std::string::npos) << help.out;
  const std::string line = help.out.substr(at + 1, help.out.find('\n', at + 1) - at - 1);
  EXPECT_EQ(line.find("without its outlines"), std::string::npos) << line;
  EXPECT_NE(line.find("the default"), std::string::npos) << line;
  const fs::path a = dir() / "plain.png", b = dir() / "no_outlines.png";
  ASSERT_EQ(run("render --size 64 48 -o " + a.string()).code, 0);
  ASSERT_EQ(run("render --size 64 48 --no-outlines -o " + b.string()).code, 0);
  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(a), bytes(b));
  // With --outlines the image differs, so the comparison above could fail.
  ASSERT_EQ(run("render --size 64 48 --outlines -o " + b.string()).code, 0);
  EXPECT_NE(bytes(a), bytes(b));
}
