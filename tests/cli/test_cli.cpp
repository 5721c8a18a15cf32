// Tier 2: the CLI contract and bad input, through the real binary.
#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <algorithm>
#include <fstream>
#include <map>
#include <vector>
#include <sstream>
#include <string>

#include "cli/cli_run.h"
#include "real_data.h"

namespace fs = std::filesystem;

namespace {

using tg::test::CmdResult;

fs::path dir() { return tg::test::cliDir("cli"); }

CmdResult run(const std::string& args) { return tg::test::runBinary(args, dir()); }

}  // namespace

TEST(Cli, DefaultSceneRendersPngOfTheRequestedSize) {
  const fs::path out = dir() / "default.png";
  fs::remove(out);
  const CmdResult r = run("render -o " + out.string() + " --size 160 120");
  ASSERT_EQ(r.code, 0) << r.err;
  auto in = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 160);
  EXPECT_EQ(in->spec().height, 120);
  EXPECT_EQ(in->spec().nchannels, 4);
  std::vector<unsigned char> px(160 * 120 * 4);
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data()));
  int lit = 0;
  for (std::size_t i = 0; i < px.size(); i += 4) lit += px[i] + px[i + 1] + px[i + 2] > 120;
  EXPECT_GT(lit, 160 * 120 / 50) << "the helix should cover a visible part of the image";
}

TEST(Cli, ExrCarriesDepthNormalAndId) {
  TG_REQUIRE_REAL_DATA();
  const fs::path out = dir() / "frame.exr";
  const CmdResult r = run("render " + tg::test::realData("slicer-fiber-tensors/fiber_vtk.vtk") + " -o " + out.string() +
                    " --size 96 64 --ortho 60 --scale-mode absolute --scale 1200 --color fa");
  ASSERT_EQ(r.code, 0) << r.err;
  auto in = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(in);
  const auto& spec = in->spec();
  const std::vector<std::string> names = {"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z", "id"};
  ASSERT_EQ(spec.nchannels, 9);
  for (int c = 0; c < 9; ++c) EXPECT_NE(std::find(spec.channelnames.begin(), spec.channelnames.end(), names[c]), spec.channelnames.end()) << names[c];
  const int zc = spec.channelindex("Z"), idc = spec.channelindex("id"), nx = spec.channelindex("N.X");
  std::vector<float> z(96 * 64), n(96 * 64 * 3);
  std::vector<std::uint32_t> id(96 * 64);
  ASSERT_TRUE(in->read_image(0, 0, zc, zc + 1, OIIO::TypeDesc::FLOAT, z.data()));
  ASSERT_TRUE(in->read_image(0, 0, idc, idc + 1, OIIO::TypeDesc::UINT, id.data()));
  ASSERT_TRUE(in->read_image(0, 0, nx, nx + 3, OIIO::TypeDesc::FLOAT, n.data()));
  int hits = 0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (id[i] == 4294967295u) {
      EXPECT_TRUE(std::isinf(z[i]));
      continue;
    }
    ++hits;
    EXPECT_LT(id[i], 1079u);
    EXPECT_TRUE(std::isfinite(z[i]));
    EXPECT_NEAR(std::sqrt(n[3 * i] * n[3 * i] + n[3 * i + 1] * n[3 * i + 1] + n[3 * i + 2] * n[3 * i + 2]), 1.0, 2e-3);
  }
  EXPECT_GT(hits, 20);
}

TEST(Cli, InfoReportsCounts) {
  TG_REQUIRE_REAL_DATA();
  const fs::path out = dir() / "info.txt";
  const std::string cmd = std::string(TG_BINARY) + " info " + tg::test::realData("tsv-kitten-stress/kitten-stress.vtu") + " > " + out.string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::ifstream in(out);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("14961 total"), std::string::npos) << text;
  EXPECT_NE(text.find("indefinite"), std::string::npos) << text;
}

TEST(Cli, SynthWritesReadableFields) {
  const fs::path d = dir();
  for (const char* f : {"helix.vtk", "helix.nrrd", "b.vti", "x.vtu", "r.vtp"}) {
    const std::string kind = f[0] == 'h' ? "helix --n 8" : f[0] == 'b' ? "boussinesq --n 6" : f[0] == 'x' ? "extremes" : "random --n 100";
    const CmdResult r = run("synth " + kind + " -o " + (d / f).string());
    ASSERT_EQ(r.code, 0) << f << ": " << r.err;
    ASSERT_TRUE(fs::file_size(d / f) > 100) << f;
  }
  const CmdResult r = run("synth random --n 1000 -o " + (d / "big.nhdr").string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream h(d / "big.nhdr");
  const std::string hdr((std::istreambuf_iterator<char>(h)), {});
  // The data file has a unique name, "big.RANDOM.raw", which the header gives.
  const auto at = hdr.find("data file: ");
  ASSERT_NE(at, std::string::npos) << hdr;
  const std::string data = hdr.substr(at + 11, hdr.find('\n', at) - at - 11);
  EXPECT_TRUE(fs::path(data).filename().string().starts_with("big.")) << data;
  EXPECT_EQ(fs::file_size(d / data), 1000u * 6 * 4);
  EXPECT_NE(hdr.find("3D-symmetric-matrix"), std::string::npos) << hdr;
}

TEST(Cli, BadInputFailsWithOneLineAndNoOutput) {
  const fs::path d = dir();
  std::ofstream(d / "empty.vtk").close();
  std::ofstream(d / "bad.vtk") << "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 1 float\n0 0 0\n"
                                  "POINT_DATA 1\nFIELD f 1\nq 4 1 float\n1 2 3 4\n";
  const fs::path out = d / "never.png";
  const std::pair<std::string, std::string> cases[] = {
      {"render " + (d / "missing.vtk").string() + " -o " + out.string(), "no such file"},
      {"render " + (d / "empty.vtk").string() + " -o " + out.string(), "empty"},
      {"render " + (d / "bad.vtk").string() + " -o " + out.string(), "4 components"},
      {"render " + d.string() + " -o " + out.string(), "directory"},
      {"render " + (d / "x.unknown").string() + " -o " + out.string(), "no such file"},
      {"render -o " + out.string() + " --size 0 10", "--size"},
      {"render -o " + out.string() + " --scale -1", "--scale"},
      {"render -o " + out.string() + " --fa-min abc", "--fa-min"},
      {"render -o " + out.string() + " --color rainbow", "--color"},
      {"render -o " + out.string() + " --fov 30 --ortho 2", "exclude"},
      {"render -o " + out.string() + " --eye 0 0 0 --look-at 0 0 0", "differ"},
      // Found by an attacker run: the next flag taken as the value, a length
      // that overflows named as a parallel up vector, a colour out of range.
      {"render -o " + out.string() + " --ortho --fov 30", "--ortho: a number is missing (found the option --fov)"},
      {"render -o " + out.string() + " --eye 1e300 1e300 1e300", "--eye must be within -3.4e+38..3.4e+38"},
      {"render -o " + out.string() + " --background 2 0 0 1", "--background must be within 0..1"},
      {"render -o " + (d / "x.notanimage").string(), "no image format"},
      {"render -o " + out.string() + " --backend vulkan", "backend"},
      {"render -o " + out.string() + " --pipeline tiles", "--pipeline: unknown glyph path \"tiles\"; choose raster, cpu, compute or auto"},
      {"render -o " + out.string() + " --pipeline cpu --glyph superquadric --tessellate 8", "--pipeline cpu casts rays; --tessellate draws a mesh"},
      {"render", "-o OUT"},
      {"info", "INPUT"},
      {"frobnicate", "unknown command"}};
  for (const auto& [args, what] : cases) tg::test::expectFailsCleanly(args, what, out, dir(), 4);
  // No temporary files left behind either.
  for (const auto& e : fs::directory_iterator(d)) EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

// The README's default image doubles as a golden image for the default scene.
TEST(Cli, DefaultSceneMatchesGoldenImage) {
  const fs::path out = dir() / "golden-check.png";
  // 800 x 600: the README's first image. The legend's text is whole multiples
  // of a 13-pixel font, so a smaller image would be mostly legend.
  const CmdResult r = run("render -o " + out.string() + " --size 800 600");
  ASSERT_EQ(r.code, 0) << r.err;
  auto a = OIIO::ImageInput::open(out.string());
  auto b = OIIO::ImageInput::open(std::string(TG_SOURCE_DIR) + "/tests/golden/default-scene.png");
  ASSERT_TRUE(a && b);
  std::vector<unsigned char> pa(800 * 600 * 4), pb(800 * 600 * 4);
  ASSERT_TRUE(a->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, pa.data()));
  ASSERT_TRUE(b->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, pb.data()));
  double sum = 0;
  int worst = 0;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    const int d = std::abs(int(pa[i]) - int(pb[i]));
    sum += d;
    worst = std::max(worst, d);
  }
  // Max 40/255: another llvmpipe build (LLVM version, SIMD width) may shade a
  // few levels differently, but a glyph gained or lost on an edge flips a
  // pixel by 100+ levels and fails. Mean 0.6/255: shading drift over the whole
  // image stays below one level on average; a moved camera or a wrong colour
  // mode shifts it by tens.
  EXPECT_LE(worst, 40);
  EXPECT_LE(sum / double(pa.size()), 0.6);
}

// The built-in scene draws its look (superquadrics, shadows, occlusion, a
// legend on images of 480 rows or more) where the flags are silent; --no-* and --glyph change it,
// and a file renders with no effect unless asked.
TEST(Cli, BuiltInSceneHasItsLookAndFilesDoNot) {
  const fs::path out = dir() / "look.png";
  auto effects = [&](const std::string& args) {
    const CmdResult r = run("render -o " + out.string() + " --size 160 120 --verbose " + args);
    EXPECT_EQ(r.code, 0) << r.err;
    std::string on;
    for (const char* e : {"shadows: map", "ambient occlusion:", "outlines:"})
      if (r.err.find(e) != std::string::npos) on += e;
    return on;
  };
  EXPECT_EQ(effects(""), "shadows: mapambient occlusion:");  // outlines only when asked
  EXPECT_EQ(effects("--no-shadows --outlines"), "ambient occlusion:outlines:");
  EXPECT_EQ(effects("--no-shadows --no-ao --no-outlines --no-legend"), "");
  const fs::path helix = dir() / "look-helix.vtk";
  ASSERT_EQ(run("synth helix --n 6 -o " + helix.string()).code, 0);
  EXPECT_EQ(effects(helix.string()), "");
  EXPECT_EQ(effects(helix.string() + " --ao"), "ambient occlusion:");
  // The look's glyph kind: the built-in scene and its plain twin differ.
  const fs::path a = dir() / "look-a.png", b = dir() / "look-b.png";
  const std::string plain = " --size 160 120 --no-shadows --no-ao --no-outlines --no-legend";
  ASSERT_EQ(run("render -o " + a.string() + plain).code, 0);
  ASSERT_EQ(run("render -o " + b.string() + plain + " --glyph ellipsoid").code, 0);
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  EXPECT_NE(std::string(std::istreambuf_iterator<char>(fa), {}), std::string(std::istreambuf_iterator<char>(fb), {}))
      << "the built-in scene draws superquadrics unless --glyph says otherwise";
  for (const std::string e : {"shadows", "ao", "outlines", "legend"}) {
    const std::string args = "render -o " + out.string() + " --" + e + " --no-" + e;
    tg::test::expectFailsCleanly(args, "--" + e + " and --no-" + e + " exclude each other", out, dir(), 1);
    EXPECT_EQ(run(args).code, 2) << args;
  }
}

// `bench accuracy` on the built-in scene, two settings: one row per setting
// with every column, error that falls as iterations rise, the frame time's
// median within its rounds' range, the default setting marked (render's
// 10 iterations and 1e-4), units under the table's header, and the plot.
TEST(Cli, BenchAccuracyWritesCsvAndPlot) {
  const fs::path csv = dir() / "acc.csv", png = dir() / "acc.png";
  fs::remove(csv);
  fs::remove(png);
  const CmdResult r =
      run("bench accuracy -o " + csv.string() + " --size 160 120 --iterations 1,10 --epsilon 1e-4 --frames 1 --repeats 3");
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(csv);
  std::string header, line;
  ASSERT_TRUE(std::getline(in, header));
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), 16);
  EXPECT_EQ(header.substr(header.rfind(",frame_ms_min")), ",frame_ms_min,frame_ms_max,repeats,default");
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 17u) << line;
    rows.push_back(v);
  }
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0][0], 1);
  EXPECT_EQ(rows[1][0], 10);
  EXPECT_EQ(rows[0][4], 1);        // one iteration allowed, one used at most
  EXPECT_GT(rows[0][5], 1.0);      // a single Newton step leaves many pixels unresolved
  EXPECT_LT(rows[1][5], 0.5);      // ten resolve them: coverage error in %
  EXPECT_GT(rows[1][2], 0.0);      // frame time
  for (const auto& row : rows) {
    EXPECT_LE(row[13], row[2]);  // min <= median <= max of the rounds
    EXPECT_LE(row[2], row[14]);
    EXPECT_EQ(row[15], 3);
  }
  EXPECT_EQ(rows[0][16], 0);  // 1 iteration: not the default
  EXPECT_EQ(rows[1][16], 1);  // 10 iterations, 1e-4: render's default
  // stdout: the header, its units, then one row per setting, the default's with a *.
  std::vector<std::string> table;
  std::stringstream out(r.out);
  for (std::string l; std::getline(out, l);) table.push_back(l);
  ASSERT_EQ(table.size(), 4u) << r.out;
  EXPECT_NE(table[1].find("[ms]"), std::string::npos) << r.out;
  EXPECT_NE(table[1].find("[deg]"), std::string::npos) << r.out;
  EXPECT_EQ(table[2].find('*'), std::string::npos) << r.out;
  EXPECT_EQ(table[3].back(), '*') << r.out;
  EXPECT_NE(r.err.find("median of 3 rounds"), std::string::npos) << r.err;
  auto plot = OIIO::ImageInput::open(png.string());
  ASSERT_TRUE(plot) << "no plot at " << png;
  EXPECT_EQ(plot->spec().width, 3 * 640);
}

TEST(Cli, BenchAccuracyRejectsBadSettingsBeforeWriting) {
  const fs::path csv = dir() / "bad.csv";
  fs::remove(csv);
  for (const char* args : {"--iterations 0", "--iterations 3,x", "--epsilon 1", "--gamma 0", "--frames 0", "--repeats 0",
                           "--repeats 101"}) {
    const CmdResult r = run("bench accuracy -o " + csv.string() + " " + args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("bench"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(csv)) << args;
  }
  EXPECT_EQ(run("bench nonsense").code, 2);
}

TEST(Cli, ViewRejectsABadScriptBeforeOpeningAWindow) {
  const auto dir = tg::test::cliDir("view_bad");
  const auto script = dir / "bad.txt";
  const auto shot = dir / "never.png";
  const std::pair<const char*, const char*> cases[] = {
      {"zoom 2\nspin 30\n", ":2: unknown command \"spin\""},
      {"gamma -1\n", ":1: gamma must be within 0..10000"},
      {"orbit 10\n", ":1: orbit: wrong number of arguments"},
      {"slab w:1\n", ":1: slab: unknown axis \"w\""},
      // Against the built-in scene's 40 x 40 x 20 grid, once it is loaded.
      {"slab k:20\n", ":1: slab k:20: index 20 is outside 0..19 along voxel axis k of the glyphs' grid"},
      {"color rainbow\n", ":1: color: unknown mode"},
      {"fa-min nan\n", ":1: fa-min"},
      {"screenshot shot.bogus\n", ":1: screenshot: no image format for \"shot.bogus\""},
  };
  for (const auto& [text, what] : cases) {
    std::ofstream(script) << text << "screenshot " << shot.string() << "\n";
    // Checked before any window: this passes without a display (plain ctest).
    tg::test::expectFailsCleanly("view --script " + script.string(), what, shot, dir, 1);
  }
  tg::test::expectFailsCleanly("view --script " + (dir / "missing.txt").string(), "no such file", shot,
                               dir, 1);
  // Attack findings: /dev/zero grew without bound, a FIFO hung, and a script
  // that screenshots onto itself was overwritten with a PNG.
  tg::test::expectFailsCleanly("view --script /dev/zero", "not a regular file", shot, dir, 1);
  const std::filesystem::path self = dir / "self.png";
  std::ofstream(self) << "screenshot " << self.string() << "\n";
  const tg::test::CmdResult r = tg::test::runBinary("view --script " + self.string(), dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("overwritten"), std::string::npos) << r.err;
  EXPECT_EQ(tg::test::slurp(self), "screenshot " + self.string() + "\n");
  std::filesystem::remove_all(dir);
}

// --help prints the options on stdout and ends there: status 0, no error,
// nothing loaded or opened (view would otherwise need a display).
TEST(Cli, HelpExitsCleanlyForEveryCommand) {
  const auto dir = tg::test::cliDir("help");
  for (const std::string cmd : {"render", "view", "info", "synth", "bench", "bench accuracy", "bench scale"}) {
    const auto r = tg::test::runBinary(cmd + " --help", dir);
    EXPECT_EQ(r.code, 0) << cmd << ": " << r.err;
    EXPECT_EQ(r.err, "") << cmd;
    EXPECT_NE(r.out.find("tensorglyph " + cmd.substr(0, cmd.find(' '))), std::string::npos) << cmd << ": " << r.out;
  }
  std::filesystem::remove_all(dir);
}

// An FA threshold outside [0, 1] hid every glyph and wrote an empty image
// with exit 0; like --cl-min and --cp-min it is a usage error now.
TEST(Cli, FaMinOutsideZeroToOneIsAUsageError) {
  const fs::path out = dir() / "famin.png";
  for (const char* v : {"2", "-0.1"}) {
    const std::string args = std::string("render -o ") + out.string() + " --fa-min " + v;
    tg::test::expectFailsCleanly(args, "--fa-min must be within 0..1", out, dir(), 1);
    EXPECT_EQ(tg::test::runBinary(args, dir()).code, 2) << args;
  }
  EXPECT_EQ(tg::test::runBinary("render -o " + out.string() + " --fa-min 1 --size 32 24", dir()).code, 0);
}

// --shadows draws a different picture of the same glyphs; its parameter flags
// are range-checked and refused without it (exit 2, no output).
TEST(Cli, ShadowsChangeThePictureAndTheirFlagsAreChecked) {
  const fs::path plain = dir() / "plain.png", shadowed = dir() / "shadowed.png";
  // The built-in scene without the rest of its look, with and without shadows.
  const std::string others = " --size 160 120 --no-ao --no-outlines --no-legend";
  ASSERT_EQ(run("render -o " + plain.string() + others + " --no-shadows").code, 0);
  const CmdResult r = run("render -o " + shadowed.string() + others + " --shadows --shadow-penumbra 0.01 "
                          "--shadow-map-size 1024 --shadow-strength 0.8 --shadow-bias 1");
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<unsigned char> a(160 * 120 * 4), b(a.size());
  auto ia = OIIO::ImageInput::open(plain.string()), ib = OIIO::ImageInput::open(shadowed.string());
  ASSERT_TRUE(ia && ib);
  ASSERT_TRUE(ia->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, a.data()));
  ASSERT_TRUE(ib->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, b.data()));
  std::size_t darker = 0, lighter = 0;
  for (std::size_t k = 0; k < a.size(); k += 4) {
    const int sa = a[k] + a[k + 1] + a[k + 2], sb = b[k] + b[k + 1] + b[k + 2];
    darker += sb + 6 < sa;
    lighter += sb > sa + 6;
  }
  EXPECT_GT(darker, 100u);  // shadows only ever take light away
  EXPECT_EQ(lighter, 0u);

  const fs::path out = dir() / "bad-shadow.png";
  const std::pair<std::string, std::string> cases[] = {
      {"--shadow-penumbra 0.01", "--shadow-penumbra needs --shadows"},
      {"--shadows --shadow-map-size 32", "--shadow-map-size must be within 64..8192"},
      {"--shadows --shadow-map-size 4294967360", "--shadow-map-size must be within 64..8192"},
      {"--shadows --shadow-penumbra -0.1", "--shadow-penumbra must be within 0..0.1"},
      {"--shadows --shadow-strength 2", "--shadow-strength must be within 0..1"},
      {"--shadows --shadow-bias nan", "--shadow-bias"}};
  for (const auto& [args, what] : cases) {
    tg::test::expectFailsCleanly("render -o " + out.string() + " " + args, what, out, dir(), 1);
    EXPECT_EQ(run("render -o " + out.string() + " " + args).code, 2) << args;
  }
}

TEST(Cli, CylinderAndBoxGlyphsRenderAndNonsenseKindsFailWithUsage) {
  const fs::path d = dir();
  for (const char* kind : {"cylinder", "box"}) {
    const fs::path out = d / (std::string(kind) + ".png");
    fs::remove(out);
    const CmdResult r = run("render -o " + out.string() + " --size 96 72 --glyph " + std::string(kind));
    EXPECT_EQ(r.code, 0) << kind << ": " << r.err;
    EXPECT_TRUE(fs::exists(out)) << kind;
  }
  const fs::path out = d / "never.png";
  const std::pair<std::string, std::string> cases[] = {
      {"--glyph cone", "--glyph: unknown kind \"cone\""},
      {"--glyph Box", "unknown kind"},
      {"--glyph box --tessellate 8", "--tessellate needs --glyph superquadric"},
      {"--glyph", "--glyph"}};
  for (const auto& [args, what] : cases) {
    tg::test::expectFailsCleanly("render -o " + out.string() + " " + args, what, out, d, 1);
    EXPECT_EQ(run("render -o " + out.string() + " " + args).code, 2) << args;
  }
}

// --stats reports the march's loop passes beside its Newton iterations. Each
// pixel that ran Newton passed through the loop once to enter and once per
// iteration, so the passes bound iterations and pixels from above; without
// --stats nothing is counted or printed.
TEST(Cli, StatsReportLoopPassesThatBoundTheNewtonIterations) {
  const fs::path field = dir() / "stats_load.vti", out = dir() / "stats.png";
  ASSERT_EQ(run("synth boussinesq --n 10 -o " + field.string() + " --quiet").code, 0);
  const std::string args =
      "render " + field.string() + " -o " + out.string() + " --glyph superquadric --gamma 3 --size 160 120";
  const CmdResult r = run(args + " --stats");
  ASSERT_EQ(r.code, 0) << r.err;
  double mean = 0;
  unsigned max = 0;
  unsigned long long pixels = 0, passes = 0;
  const auto at = r.err.find("Newton iterations:");
  ASSERT_NE(at, std::string::npos) << r.err;
  ASSERT_EQ(std::sscanf(r.err.c_str() + at, "Newton iterations: mean %lf, max %u over %llu pixels; %llu march loop passes",
                        &mean, &max, &pixels, &passes),
            4)
      << r.err;
  EXPECT_GT(pixels, 100u);
  EXPECT_GE(mean, 1.0);
  EXPECT_LE(mean, max);
  // mean is printed to 0.01.
  EXPECT_GE(static_cast<double>(passes), static_cast<double>(pixels) * (mean - 0.005 + 1.0));
  const CmdResult quiet = run(args);
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err.find("march loop passes"), std::string::npos) << quiet.err;
}
