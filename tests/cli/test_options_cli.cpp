// Options that failed without a word: every numeric option at its extremes,
// options given twice, flags without the flag they depend on, and names that
// would split a message's line. Through the real binary.
#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using tg::test::CmdResult;

fs::path dir() { return tg::test::cliDir("options"); }
CmdResult run(const std::string& args) { return tg::test::runBinary(args, dir()); }

// A 3 x 3 x 2 helix: 18 glyphs, drawn in a fraction of a second.
const fs::path& field() {
  static const fs::path f = [] {
    const fs::path p = dir() / "helix.nrrd";
    const CmdResult r = run("synth helix --n 3 -o " + p.string());
    EXPECT_EQ(r.code, 0) << r.err;
    return p;
  }();
  return f;
}

// Pixels that differ from `bg` (8-bit RGB); -1 when the image cannot be read.
long drawnPixels(const fs::path& png, const unsigned char bg[3]) {
  auto in = OIIO::ImageInput::open(png.string());
  if (!in) return -1;
  const int w = in->spec().width, h = in->spec().height;
  std::vector<unsigned char> px(std::size_t(w) * std::size_t(h) * 4);
  if (!in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data())) return -1;
  long n = 0;
  for (std::size_t i = 0; i < px.size(); i += 4) n += px[i] != bg[0] || px[i + 1] != bg[1] || px[i + 2] != bg[2];
  return n;
}

// Every numeric option of `render`, how its values are given ({} stands for
// the value) and what it needs beside it to have an effect.
struct NumericCase {
  std::string flag, values, needs;
};
const std::vector<NumericCase>& numericCases() {
  static const std::vector<NumericCase> cases = {
      {"--fa-min", "{}", ""},
      {"--mask-min", "{}", "--mask MASK"},
      {"--confidence-min", "{}", ""},
      {"--stride", "{}", ""},
      {"--roi", "{} {} {} 5 5 5", ""},
      {"--cl-min", "{}", ""},
      {"--cp-min", "{}", ""},
      {"--iterations", "{}", "--glyph superquadric"},
      {"--epsilon", "{}", "--glyph superquadric"},
      {"--gamma", "{}", "--glyph superquadric"},
      {"--blob-threshold", "{}", "--glyph blob"},
      {"--blobbiness", "{}", "--glyph blob"},
      {"--blob-cutoff", "{}", "--glyph blob"},
      {"--blob-steps", "{}", "--glyph blob"},
      {"--min-eigenvalue", "{}", ""},
      {"--scale", "{}", ""},
      {"--lambda0", "{}", "--magnitude shape"},
      {"--lambda0", "{}", "--magnitude log"},
      {"--clamp", "{}", ""},
      {"--tessellate", "{}", "--glyph superquadric"},
      {"--background", "{} {} {} 1", ""},
      {"--legend-text-scale", "{}", "--legend"},
      {"--eye", "{} {} {}", ""},
      {"--eye", "0 0 {}", ""},
      {"--look-at", "{} {} {}", "--eye 1 1 20"},
      {"--color-range", "0 {}", "--color vonmises"},
      {"--up", "{} {} {}", "--eye 1 1 20"},
      {"--fov", "{}", ""},
      {"--ortho", "{}", ""},
      {"--plane-at", "1 1 1 {} {} {}", "--underlay fa"},
      {"--underlay-window", "{} 1", "--underlay fa"},
      {"--underlay-percentiles", "{} 100", "--underlay fa"},
      {"--plane-offset", "{}", "--underlay fa"},
      {"--mesh-color", "{} {} {}", "--mesh MESH"},
      {"--mesh-opacity", "{}", "--mesh MESH --mesh-mode see-through"},
      {"--mesh-feature-angle", "{}", "--mesh MESH --mesh-mode edges"},
      {"--tract-color", "{} {} {}", "--tracts TRACTS"},
      {"--tract-width", "{}", "--tracts TRACTS"},
      {"--ao-radius", "{}", "--ao"},
      {"--ao-strength", "{}", "--ao"},
      {"--ao-samples", "{}", "--ao"},
      {"--outline-width", "{}", "--outlines"},
      {"--outline-color", "{} {} {} 1", "--outlines"},
      {"--outline-crease", "{}", "--outlines"},
      {"--shadow-penumbra", "{}", "--shadows"},
      {"--shadow-map-size", "{}", "--shadows"},
      {"--shadow-strength", "{}", "--shadows"},
      {"--shadow-bias", "{}", "--shadows"},
      {"--size", "{} {}", ""},
      {"--samples", "{}", ""},
      {"--pick", "{} {}", ""},
      {"--repeat", "{}", ""},
  };
  return cases;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size()) s.replace(at, from.size(), to);
  return s;
}

}  // namespace

// The class of `--fov 1e-10`, `--ortho 1e-20`, `--magnitude shape --lambda0
// 1e-39` (blank images, exit 0) and `--min-eigenvalue 1e300` (blamed on the
// data): every numeric option, at each extreme, is refused naming it (exit 2)
// or draws something, or says on stderr, naming it, why nothing shows.
TEST(Options, EveryNumericOptionAtItsExtremesIsRefusedOrDraws) {
  const fs::path mesh = dir() / "tri.obj", mask = dir() / "mask.nrrd", out = dir() / "extreme.png";
  const fs::path tracts = dir() / "line.tck";
  {
    std::ofstream(mesh) << "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n";
    // One streamline across the mesh's triangle: MRtrix's header, float32 points, NaN and Inf ends.
    const std::string head = "mrtrix tracks\ndatatype: Float32LE\nfile: . 50\nEND\n";
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const float points[] = {0, 0, 0, 1, 1, 0, 2, 2, 0, nan, nan, nan, inf, inf, inf};
    std::ofstream(tracts, std::ios::binary) << head << std::string(50 - head.size(), ' ')
                                            << std::string(reinterpret_cast<const char*>(points), sizeof points);
    std::ofstream m(mask);
    m << "NRRD0004\ntype: float\ndimension: 3\nsizes: 3 3 2\nencoding: ascii\n\n";
    for (int k = 0; k < 18; ++k) m << "1\n";
  }
  for (const NumericCase& c : numericCases())
    for (const std::string v : {"0", "-1", "1e-40", "1e300", "nan", "inf", "1e-20", "1e20"}) {
      fs::remove(out);
      const std::string needs =
          replaced(replaced(replaced(c.needs, "MESH", mesh.string()), "MASK", mask.string()), "TRACTS", tracts.string());
      // --size is the option under test there; elsewhere a small image.
      const std::string size = c.flag == "--size" ? "" : " --size 64 48";
      const std::string args = "render " + field().string() + " -o " + out.string() + size + " " + needs + " " +
                               c.flag + " " + replaced(c.values, "{}", v);
      const CmdResult r = run(args);
      if (r.code == 0) {
        unsigned char bg[3] = {20, 20, 26};
        if (c.flag == "--background") std::fill(bg, bg + 3, static_cast<unsigned char>(v == "0" || v == "1e-40" || v == "1e-20" ? 0 : 255));
        // A blank image comes only with a line naming the option as the reason
        // (--scale 1e-20: "the typical glyph is 2e-22 pixels across ...").
        const long drawn = drawnPixels(out, bg);
        EXPECT_GE(drawn, 0) << args;
        if (drawn == 0) {
          EXPECT_NE(r.err.find(c.flag), std::string::npos) << args << " drew a blank image: " << r.err;
        }
      } else {
        // 2, or 1 where the value is fine but leaves no sample of this field
        // (--roi far away): either way the option is named.
        EXPECT_TRUE(r.code == 2 || (r.code == 1 && (c.flag == "--roi" || c.flag == "--mask-min"))) << args << " -> " << r.err;
        EXPECT_NE(r.err.find(c.flag), std::string::npos) << args << " -> " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << " -> " << r.err;
        EXPECT_FALSE(fs::exists(out)) << args;
      }
    }
}

// The list above is every numeric option the table declares: one added
// without a case here fails.
TEST(Options, EveryRangedOptionOfRenderHasAnExtremesCase) {
  const CmdResult r = run("render --help-markdown");
  ASSERT_EQ(r.code, 0) << r.err;
  std::set<std::string> covered;
  for (const NumericCase& c : numericCases()) covered.insert(c.flag);
  std::istringstream lines(r.out);
  int ranged = 0;
  for (std::string line; std::getline(lines, line);) {
    // | `--flag` | `VALUES` | RANGE | help |
    if (!line.starts_with("| `-")) continue;
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
    ASSERT_GE(cells.size(), 4u) << line;
    const std::string flag = cells[1].substr(cells[1].rfind('`', cells[1].rfind('`') - 1) + 1,
                                             cells[1].rfind('`') - cells[1].rfind('`', cells[1].rfind('`') - 1) - 1);
    if (cells[3].find_first_not_of(' ') == std::string::npos) continue;
    ++ranged;
    EXPECT_TRUE(covered.count(flag)) << flag << " has a range but no case in numericCases()";
  }
  EXPECT_GT(ranged, 30);
}

TEST(Options, ASingleValuedOptionGivenTwiceIsRefused) {
  const fs::path a = dir() / "a.png", b = dir() / "b.png";
  for (const std::string& twice :
       {"-o " + a.string() + " -o " + b.string(), "-o " + b.string() + " --size 64 48 --size 80 60",
        "-o " + b.string() + " --glyph box --glyph ellipsoid", "-o " + b.string() + " --color fa --color dec",
        "-o " + b.string() + " --gamma 2 --gamma 3"}) {
    fs::remove(a);
    fs::remove(b);
    const CmdResult r = run("render " + twice);
    EXPECT_EQ(r.code, 2) << twice;
    EXPECT_NE(r.err.find("is given more than once"), std::string::npos) << twice << " -> " << r.err;
    EXPECT_FALSE(fs::exists(a) || fs::exists(b)) << twice;
  }
  // What is meant to repeat still does, and a switch twice says the same.
  const CmdResult r = run("render " + field().string() + " -o " + b.string() +
                          " --size 64 48 --plane z:0 --plane z:1 --pick 1 1 --pick 2 2 --legend --legend");
  EXPECT_EQ(r.code, 0) << r.err;
  const CmdResult info = run("info " + field().string() + " --stride 1 --stride 2");
  EXPECT_EQ(info.code, 2);
  EXPECT_NE(info.err.find("--stride is given more than once"), std::string::npos) << info.err;
}

TEST(Options, DependentFlagsWithoutTheirMasterAreRefused) {
  const fs::path out = dir() / "dependent.png";
  std::ofstream(dir() / "tri.obj") << "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n";
  for (const auto& [args, what] : std::vector<std::pair<std::string, std::string>>{
           {"--mask-min 0.3", "--mask-min needs --mask"},
           {"--look-at 0 0 0", "--look-at and --up need --eye"},
           {"--shadow-bias 2", "--shadow-bias needs --shadows"},
           {"--ao-radius 2", "need --ao"},
           {"--outline-width 2", "need --outlines"},
           {"--legend-corner top-left", "need --legend"},
           {"--plane-offset 1", "--plane-offset needs --underlay or --plane"},
           {"--mesh-opacity 0.5", "--mesh-opacity needs --mesh"},
           {"--lambda0 1", "--lambda0 applies to --magnitude log or shape only"},
           {"--stats", "--stats applies to --glyph superquadric only"},
           {"--blob-steps 2", "--blob-steps applies to --glyph blob only"},
           {"--mesh MESH --mesh-opacity 0.5", "--mesh-opacity applies to --mesh-mode see-through"},
           {"--mesh MESH --mesh-mode see-through --mesh-feature-angle 30",
            "--mesh-feature-angle applies to --mesh-mode edges"}}) {
    const std::string cmd = "render " + field().string() + " -o " + out.string() + " " +
                            replaced(args, "MESH", (dir() / "tri.obj").string());
    tg::test::expectFailsCleanly(cmd, what, out, dir(), 1);
    EXPECT_EQ(run(cmd).code, 2) << args;
  }
}

// A name holding a newline or a terminal's escape sequence stays inside one
// line of the message, escaped.
TEST(Options, ControlCharactersInNamesAreEscapedInMessages) {
  const fs::path out = dir() / "escaped.png";
  const std::string name = (dir() / "a\nb\x1b[31m.nrrd").string();
  for (const std::string& args : {"render '" + name + "' -o " + out.string(), "info '" + name + "'",
                                  "render -o '" + (dir() / "x\ny.png").string() + "' --mask '" + name + "'"}) {
    const CmdResult r = run(args);
    EXPECT_NE(r.code, 0) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\\n"), std::string::npos) << r.err;
  }
}

// γ and its neighbours have one range each: render, info, both benchmarks
// and the GPU executable refuse the same values in the same words.
TEST(Options, EveryCommandRefusesARangeInTheSameWords) {
  const fs::path csv = dir() / "same.csv", png = dir() / "same.png";
  const std::map<std::string, std::vector<std::string>> surfaces = {
      {" must be within 0..10000", {"render -o " + png.string() + " --gamma ", "bench accuracy -o " + csv.string() + " --gamma ",
                                    "bench scale -o " + csv.string() + " --gamma "}},
      {" must be within 1..1000", {"render -o " + png.string() + " --glyph superquadric --iterations ",
                                   "bench accuracy -o " + csv.string() + " --iterations "}},
      {" must be within 1e-09..0.5", {"render -o " + png.string() + " --glyph superquadric --epsilon ",
                                      "bench accuracy -o " + csv.string() + " --epsilon "}},
      {" must be within 1..1e+06", {"render -o " + png.string() + " --stride ", "info " + field().string() + " --stride ",
                                    "bench accuracy -o " + csv.string() + " --stride "}},
      {" must be within 0 (off) or 0.01..1e+06",
       {"render -o " + png.string() + " --clamp ", "info " + field().string() + " --clamp "}},
  };
  for (const auto& [words, commands] : surfaces)
    for (const std::string& cmd : commands)
      for (const std::string v : {"-1", "1e300", "2000000"}) {
        const CmdResult r = run(cmd + v);
        EXPECT_EQ(r.code, 2) << cmd << v;
        EXPECT_NE(r.err.find(words), std::string::npos) << cmd << v << " -> " << r.err;
      }
  const CmdResult gpu = tg::test::runBinary("-o " + csv.string() + " --gamma 20000", dir(), TG_GPUBENCH);
  EXPECT_EQ(gpu.code, 2);
  EXPECT_NE(gpu.err.find("--gamma must be within 0..10000"), std::string::npos) << gpu.err;
}

// --help is grouped by task, each group with an example; `help TOPIC` prints
// one group; -q is --quiet.
TEST(Options, HelpIsGroupedByTaskAndHelpTopicPrintsOneGroup) {
  const CmdResult help = run("render --help");
  ASSERT_EQ(help.code, 0) << help.err;
  std::size_t at = 0;
  for (const char* group : {"input and selection:", "glyphs:", "colour:", "camera and views:", "context:",
                            "depth cues:", "output:"}) {
    const std::size_t found = help.out.find(std::string("\n") + group + "\n", at);
    ASSERT_NE(found, std::string::npos) << group << " missing or out of order";
    const std::size_t example = help.out.find("e.g. tensorglyph render", found);
    EXPECT_NE(example, std::string::npos) << group;
    at = found + 1;
  }
  const CmdResult camera = run("help camera");
  ASSERT_EQ(camera.code, 0) << camera.err;
  EXPECT_EQ(camera.out.find("camera and views:\n"), 0u) << camera.out;
  EXPECT_NE(camera.out.find("--fov DEG"), std::string::npos);
  EXPECT_EQ(camera.out.find("--gamma"), std::string::npos) << "another group's option";
  EXPECT_EQ(run("help depth").out.find("depth cues:\n"), 0u);
  EXPECT_NE(run("help").out.find("input and selection"), std::string::npos);
  EXPECT_NE(run("help info").out.find("usage: tensorglyph info"), std::string::npos);
  const CmdResult formats = run("help formats");
  ASSERT_EQ(formats.code, 0) << formats.err;
  for (const char* row : {"NIfTI: .nii .nii.gz; as input, --mask/--underlay; --layout, --frame; module nifti (loads)",
                          "MRtrix: .mif .mih; as input, --mask/--underlay; no format options; read by tensorglyph itself",
                          "STL: .stl; as --mesh; no format options; module vtk (loads)"})
    EXPECT_NE(formats.out.find(row), std::string::npos) << row << "\n" << formats.out;
  const CmdResult unknown = run("help lighting");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("unknown topic \"lighting\""), std::string::npos) << unknown.err;
  const fs::path out = dir() / "quiet.png";
  const CmdResult quiet = run("render " + field().string() + " -q --size 32 24 -o " + out.string());
  EXPECT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(run("info " + field().string() + " -q").code, 0);
}

// docs/cli.md is the build's reference (generated from the option tables),
// committed: a change to an option without it fails here.
TEST(Options, CommittedCommandReferenceIsTheGeneratedOne) {
  const std::string committed = tg::test::slurp(fs::path(TG_SOURCE_DIR) / "docs" / "cli.md");
  const std::string generated = tg::test::slurp(TG_CLI_REFERENCE);
  ASSERT_FALSE(generated.empty()) << TG_CLI_REFERENCE;
  EXPECT_NE(generated.find("| `--gamma` | `G` | 0..10000 |"), std::string::npos);
  EXPECT_TRUE(committed == generated) << "docs/cli.md is stale: copy " << TG_CLI_REFERENCE << " over it";
}

// docs/script.md likewise, from the script's command table; `help script`
// prints the same commands.
TEST(Options, CommittedScriptReferenceIsTheGeneratedOne) {
  const std::string committed = tg::test::slurp(fs::path(TG_SOURCE_DIR) / "docs" / "script.md");
  const std::string generated = tg::test::slurp(TG_SCRIPT_REFERENCE);
  ASSERT_FALSE(generated.empty()) << TG_SCRIPT_REFERENCE;
  EXPECT_TRUE(committed == generated) << "docs/script.md is stale: copy " << TG_SCRIPT_REFERENCE << " over it";
  const tg::test::CmdResult help = tg::test::runBinary("help script", tg::test::cliDir("help_script"));
  ASSERT_EQ(help.code, 0) << help.err;
  for (const char* verb : {"orbit", "slab", "plane", "view", "screenshot", "pick"}) {
    EXPECT_NE(generated.find(std::string("| `") + verb + "` |"), std::string::npos) << verb;
    EXPECT_NE(help.out.find(std::string("\n  ") + verb + " "), std::string::npos) << verb;
  }
  EXPECT_NE(help.out.find("i|j|k:INDEX[:THICKNESS]"), std::string::npos) << "slab's slices, as --slice's";
}
