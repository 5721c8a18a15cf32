// --tracts through the real binary: Slicer's fibre tensors with their own
// polylines and a .tck drawn beside them, picked as tracts; and hostile
// tract files (truncated, lying counts, wrong magic, NaN, no lines, a
// directory), each failing with exit 1 and one line naming the file, under
// an address-space limit; misuse of the flags with exit 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <json/json.h>

#include "cli/cli_run.h"

namespace fs = std::filesystem;
using tg::test::CmdResult;

namespace {

constexpr long kVirtualKiB = 1536 * 1024;  // as tests/cli/test_hostile.cpp
const std::string kFibres = std::string(TG_REAL_DATA_DIR) + "/slicer-fiber-tensors/fiber_vtk.vtk";

const fs::path& dir() {
  static const fs::path d = tg::test::cliDir("tracts");
  return d;
}

CmdResult run(const std::string& args) {
  return tg::test::runBinary("", dir(), "ulimit -v " + std::to_string(kVirtualKiB) + "; exec " TG_BINARY " " + args);
}

// A .tck of float32 triplets after its header.
fs::path tck(const std::string& name, const std::vector<float>& v, const std::string& extraHeader = "") {
  const std::string head = "mrtrix tracks\n" + extraHeader + "datatype: Float32LE\nfile: . ";
  std::string h = head + "00\nEND\n";
  h = head + std::to_string(h.size()) + "\nEND\n";
  const fs::path p = dir() / name;
  std::ofstream(p, std::ios::binary) << h << std::string(reinterpret_cast<const char*>(v.data()), 4 * v.size());
  return p;
}

// A straight streamline along x through (cx, cy, cz), 40 mm long.
std::vector<float> lineAlongX(float cx, float cy, float cz) {
  std::vector<float> v;
  for (int k = 0; k <= 40; ++k) v.insert(v.end(), {cx - 20.0f + float(k), cy, cz});
  v.insert(v.end(), {NAN, NAN, NAN, INFINITY, INFINITY, INFINITY});
  return v;
}

Json::Value parse(const std::string& line) {
  Json::Value v;
  std::istringstream in(line);
  in >> v;
  return v;
}

}  // namespace

TEST(TractsCli, DrawnWithTheGlyphsAndPickedAsTracts) {
  ASSERT_TRUE(fs::exists(kFibres)) << kFibres;
  // The fibres' box is x -14.5..20.5, y 10.9..21.3, z 17.6..56.1: a line
  // through its middle, seen from +z with the centre pixel on its axis.
  const fs::path line = tck("line.tck", lineAlongX(3.0f, 16.0f, 37.0f));
  const fs::path out = dir() / "picked.png";
  const std::string camera = " --eye 3 16 137 --look-at 3 16 37 --up 0 1 0 --size 200 150";
  const CmdResult r = run("render " + kFibres + " --tracts " + kFibres + " --tracts " + line.string() +
                          " --tract-width 2" + camera + " -o " + out.string() + " --pick 100 75 --pick 100 5");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_TRUE(fs::exists(out));
  std::istringstream lines(r.out);
  std::string first, second;
  std::getline(lines, first);
  std::getline(lines, second);
  const Json::Value hit = parse(first), miss = parse(second);
  EXPECT_EQ(hit["hit"].asString(), "context") << first;
  EXPECT_EQ(hit["label"].asString(), "tracts line.tck") << first;
  // On the tube's surface: its radius (1 mm) from the axis, towards the eye.
  const double dy = hit["surface"][1].asDouble() - 16.0, dz = hit["surface"][2].asDouble() - 37.0;
  EXPECT_NEAR(std::hypot(dy, dz), 1.0, 0.05) << first;
  EXPECT_GT(dz, 0.9) << first;
  EXPECT_EQ(miss["hit"].asString(), "background") << second;
  // The picture changes with the tracts, and with their colour.
  const fs::path plain = dir() / "plain.png", red = dir() / "red.png";
  ASSERT_EQ(run("render " + kFibres + camera + " -o " + plain.string()).code, 0);
  ASSERT_EQ(run("render " + kFibres + " --tracts " + line.string() + " --tract-width 2 --tract-color 1 0 0" + camera +
                " -o " + red.string()).code, 0);
  EXPECT_NE(tg::test::slurp(plain), tg::test::slurp(out));
  EXPECT_NE(tg::test::slurp(red), tg::test::slurp(out));
  // --verbose says what was drawn.
  const CmdResult stats = run("render " + kFibres + " --tracts " + kFibres + " --verbose -o " + plain.string());
  EXPECT_NE(stats.err.find("tracts fiber_vtk.vtk: 8 streamlines, 1071 segments"), std::string::npos) << stats.err;
}

TEST(TractsCli, HostileTractFilesFailInOneLine) {
  ASSERT_TRUE(fs::exists(kFibres)) << kFibres;
  std::vector<float> good = lineAlongX(0, 0, 0);
  struct Case {
    fs::path file;
    std::string what;
  };
  std::vector<float> nan = good;
  for (float& x : nan)
    if (std::isfinite(x)) x = NAN;
  nan[3] = 1.0f;  // one point left finite in a NaN streamline: it is dropped whole
  std::vector<float> cut = good;
  cut.resize(cut.size() - 2);
  const fs::path noLines = dir() / "nolines.vtk";
  std::ofstream(noLines) << "# vtk DataFile Version 4.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
                            "POLYGONS 1 4\n3 0 1 2\n";
  const fs::path wrongMagic = dir() / "magic.trk";
  std::ofstream(wrongMagic, std::ios::binary) << std::string(1000, 'x');
  // A .trk that says it holds 2^31 - 1 streamlines, the first of 2^31 - 1 points.
  std::string trk(1004, '\0');
  std::memcpy(trk.data(), "TRACK", 5);
  const std::int16_t dims[3] = {10, 10, 10};
  const float sizes[3] = {1, 1, 1};
  const std::int32_t count = 0x7fffffff, version = 2, hdr = 1000;
  std::memcpy(trk.data() + 6, dims, 6);
  std::memcpy(trk.data() + 12, sizes, 12);
  for (int k = 0; k < 4; ++k) {
    const float one = 1.0f;
    std::memcpy(trk.data() + 440 + 20 * k, &one, 4);
  }
  std::memcpy(trk.data() + 948, "RAS", 3);
  std::memcpy(trk.data() + 988, &count, 4);
  std::memcpy(trk.data() + 992, &version, 4);
  std::memcpy(trk.data() + 996, &hdr, 4);
  std::memcpy(trk.data() + 1000, &count, 4);
  const fs::path huge = dir() / "huge.trk";
  std::ofstream(huge, std::ios::binary) << trk;
  fs::create_directories(dir() / "adir.tck");
  const std::vector<Case> cases = {
      {tck("cut.tck", cut), "not a whole number of 12-byte points: truncated"},
      {tck("nan.tck", nan), "nothing to draw"},
      {tck("count.tck", good, "count: 99999999999999\n"), ""},
      {noLines, "no polylines (LINES)"},
      {wrongMagic, "does not begin with \"TRACK\""},
      {huge, "truncated, or the count is wrong"},
      {dir() / "adir.tck", "is a directory"},
      {dir() / "missing.trk", "no such file"},
  };
  const fs::path out = dir() / "hostile.png";
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file.string());
    fs::remove(out);
    const CmdResult r = run("render " + kFibres + " --tracts " + c.file.string() + " -o " + out.string());
    if (c.what.empty()) {  // a count is never trusted, nor needed
      EXPECT_EQ(r.code, 0) << r.err;
      continue;
    }
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find(c.what), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.file.string()), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  // A NaN streamline beside good ones is skipped with a warning.
  std::vector<float> mixed = good;
  mixed.resize(mixed.size() - 3);
  mixed.insert(mixed.end(), {1, 1, NAN, 2, 2, 2, NAN, NAN, NAN, INFINITY, INFINITY, INFINITY});
  const CmdResult warned = run("render " + kFibres + " --tracts " + tck("mixed.tck", mixed).string() + " -o " + out.string());
  EXPECT_EQ(warned.code, 0) << warned.err;
  EXPECT_NE(warned.err.find("1 streamlines skipped: a point is NaN/Inf"), std::string::npos) << warned.err;
  // A tract file as the tensor input says where it belongs.
  const CmdResult asInput = run("render " + tck("input.tck", good).string() + " -o " + out.string());
  EXPECT_EQ(asInput.code, 1) << asInput.err;
  EXPECT_NE(asInput.err.find("MRtrix tracks holds streamlines, not tensors: give it with --tracts"), std::string::npos)
      << asInput.err;
  // An output that is a --tracts input (a hard link under an image's name)
  // is refused by render's -o and by the viewer's screenshot alike, before
  // anything is read or written.
  const fs::path input = tck("linked.tck", good), linked = dir() / "linked.png", script = dir() / "shot.tgs";
  fs::remove(linked);
  fs::create_hard_link(input, linked);
  std::ofstream(script) << "screenshot " << linked.string() << "\n";
  const auto before = fs::file_size(input);
  for (const std::string& cmd : {"render " + kFibres + " --tracts " + input.string() + " -o " + linked.string(),
                                 "view " + kFibres + " --tracts " + input.string() + " --script " + script.string()}) {
    const CmdResult r = run(cmd);
    EXPECT_EQ(r.code, 2) << cmd << " -> " << r.err;
    EXPECT_NE(r.err.find("is the --tracts file; it would be overwritten"), std::string::npos) << cmd << " -> " << r.err;
    EXPECT_EQ(fs::file_size(input), before);
  }
  // Misuse of the flags: exit 2 before anything is read.
  for (const auto& [args, what] :
       {std::pair<std::string, std::string>{"--tract-width 2", "--tract-width needs --tracts"},
        {"--tract-color 1 0 0", "--tract-color needs --tracts"},
        {"--tracts a.stl", "unknown tractography extension \".stl\""},
        {"--tracts x.tck --tract-width 0", "--tract-width"}}) {
    const CmdResult r = run("render " + kFibres + " " + args + " -o " + out.string());
    EXPECT_EQ(r.code, 2) << args << " -> " << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << args << " -> " << r.err;
  }
}
