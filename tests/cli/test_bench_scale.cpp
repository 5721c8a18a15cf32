// The scale sweep, through `tensorglyph bench scale` and through the EGL-only
// executable that is carried to GPU machines.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_run.h"

namespace {

using Row = std::map<std::string, std::string>;

// Rows keyed by the header's column names, so a reordered CSV still reads.
std::vector<Row> readCsv(const std::filesystem::path& p) {
  std::istringstream in(tg::test::slurp(p));
  // Fields split at commas outside double quotes (the device name has commas).
  auto split = [](const std::string& line) {
    std::vector<std::string> c(1);
    bool quoted = false;
    for (char ch : line) {
      if (ch == '"')
        quoted = !quoted;
      else if (ch == ',' && !quoted)
        c.emplace_back();
      else
        c.back() += ch;
    }
    return c;
  };
  std::string line;
  std::getline(in, line);
  const auto header = split(line);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    const auto c = split(line);
    EXPECT_EQ(c.size(), header.size()) << line;
    Row r;
    for (std::size_t k = 0; k < std::min(c.size(), header.size()); ++k) r[header[k]] = c[k];
    rows.push_back(r);
  }
  return rows;
}

double num(const Row& r, const std::string& col) { return std::stod(r.at(col)); }

const std::string kSweep = "--n 300,1000 --size 96 64 --resolutions 4,16 --frames 1 -o ";

// What both executables must write for kSweep: one row per method and count,
// with times, memory and coverage that hold on any renderer.
std::map<std::string, double> checkSweep(const std::vector<Row>& rows) {
  std::map<std::string, double> coverage;
  std::map<std::string, std::string> coveredPct;  // method and count
  EXPECT_EQ(rows.size(), 20u);  // (7 raster + 3 compute methods) x 2 counts
  for (const Row& r : rows) {
    const std::string m = r.at("method");
    const bool compute = r.at("pipeline") == "compute";
    EXPECT_EQ(compute, m.rfind("compute-", 0) == 0) << m;
    const bool noPrepass = m.size() > 11 && m.substr(m.size() - 11) == "-no-prepass";
    coveredPct[m + " " + r.at("n")] = r.at("covered_pct");
    EXPECT_EQ(r.at("frames"), "1") << m;
    EXPECT_GT(num(r, "frame_ms"), 0.0) << m;
    EXPECT_GT(num(r, "gpu_ms"), 0.0) << m;
    // The compute path's tile lists start at a fixed size, whatever the count.
    if (!compute) {
      EXPECT_LE(num(r, "gpu_bytes_per_glyph"), 64.0) << m;
    }
    EXPECT_GE(num(r, "gpu_bytes_per_glyph"), 48.0) << m;  // the records
    // Whether the timed frames ran the pre-pass: never where it is off.
    EXPECT_TRUE(r.at("prepass") == "0" || (r.at("prepass") == "1" && !noPrepass)) << m << " " << r.at("prepass");
    if (m.find("sprites-subpixel") != std::string::npos) {
      // Under a pixel per glyph: nearly nothing covered, and no shape to score.
      EXPECT_LT(num(r, "covered_pct"), 1.0);
      EXPECT_EQ(r.at("coverage_error_pct"), "");
      continue;
    }
    EXPECT_GT(num(r, "covered_pct"), 5.0) << m;
    // The compute path keeps no march counts.
    EXPECT_EQ(r.at("newton_mean").empty(), m.rfind("raycast-superquadric", 0) != 0) << m;
    EXPECT_EQ(r.at("vtk_mesh_bytes_per_glyph").empty(), m.rfind("tessellated-", 0) != 0) << m;
    coverage[m] = num(r, "coverage_error_pct");
  }
  // The pre-pass only skips hidden work: the same pixels, the same error.
  for (const char* n : {"300", "1000"}) {
    EXPECT_EQ(coveredPct[std::string("raycast-superquadric ") + n],
              coveredPct[std::string("raycast-superquadric-no-prepass ") + n]);
    EXPECT_EQ(coveredPct[std::string("sprites-subpixel ") + n],
              coveredPct[std::string("sprites-subpixel-no-prepass ") + n]);
  }
  EXPECT_EQ(coverage["raycast-superquadric"], coverage["raycast-superquadric-no-prepass"]);
  // The compute path casts the raster path's pixels.
  for (const char* n : {"300", "1000"}) {
    EXPECT_EQ(coveredPct[std::string("compute-superquadric ") + n], coveredPct[std::string("raycast-superquadric ") + n]);
    EXPECT_EQ(coveredPct[std::string("compute-ellipsoid ") + n], coveredPct[std::string("raycast-ellipsoid ") + n]);
  }
  EXPECT_EQ(coverage["compute-superquadric"], coverage["raycast-superquadric"]);
  EXPECT_EQ(coverage["compute-ellipsoid"], coverage["raycast-ellipsoid"]);
  // The exact ray casts beat the coarse mesh, which the finer mesh improves on.
  EXPECT_LT(coverage["raycast-superquadric"], coverage["tessellated-4"]);
  EXPECT_LT(coverage["tessellated-16"], coverage["tessellated-4"]);
  return coverage;
}

TEST(BenchScale, WritesOneRowPerMethodAndCount) {
  const auto dir = tg::test::cliDir("bench_scale");
  const auto csv = dir / "scale.csv";
  const auto r = tg::test::runBinary("bench scale " + kSweep + csv.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  checkSweep(readCsv(csv));
  tg::test::expectFailsCleanly("bench scale --n 0 -o " + csv.string(), "--n", csv, dir, 1);
  tg::test::expectFailsCleanly("bench scale --resolutions 2 -o " + csv.string(), "--resolutions", csv, dir, 1);
  tg::test::expectFailsCleanly("bench scale --size 96 -o " + csv.string(), "--size", csv, dir, 1);
  tg::test::expectFailsCleanly("bench scale --bogus -o " + csv.string(), "--bogus", csv, dir, 1);
  tg::test::expectFailsCleanly("bench scale --require-gpu -o " + csv.string(), "--require-gpu", csv, dir, 1);
  tg::test::expectFailsCleanly("bench scale --pipelines raster,tiles -o " + csv.string(), "--pipelines: \"tiles\"; choose raster, cpu, compute", csv, dir, 1);
  tg::test::expectFailsCleanly("bench scale --pipelines raster,raster -o " + csv.string(), "named twice", csv, dir, 1);
  tg::test::expectFailsCleanly("bench scale --row-budget 0 -o " + csv.string(), "--row-budget", csv, dir, 1);
  tg::test::expectFailsCleanly("bench scale --pipelines compute, -o " + csv.string(), "--pipelines: an empty name", csv, dir, 1);
  tg::test::expectFailsCleanly("bench scale --n 100,100 -o " + csv.string(), "--n: 100 is named twice", csv, dir, 1);
  std::filesystem::remove_all(dir);
}

// The CSV is whole after every row: a sweep out of time keeps the rows it
// finished and names the budget; --row-budget cuts a row's timed frames
// (at least one), and --pipelines picks the paths and their order.
TEST(BenchScale, BudgetsCutRowsAndFramesAndTheCsvKeepsWhatRan) {
  const auto dir = tg::test::cliDir("bench_scale_budget");
  const auto csv = dir / "scale.csv";
  auto r = tg::test::runBinary("bench scale --n 300,1000 --size 96 64 --pipelines compute,cpu --frames 50 "
                               "--row-budget 0.001 -o " + csv.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  auto rows = readCsv(csv);
  ASSERT_EQ(rows.size(), 12u);  // 3 methods x 2 paths x 2 counts
  EXPECT_EQ(rows[0].at("pipeline"), "compute");
  EXPECT_EQ(rows[3].at("pipeline"), "cpu");
  EXPECT_EQ(rows[3].at("method"), "cpu-ellipsoid");
  // Each frame takes well over 0.1 ms here, so that 1 ms holds a few of the 50.
  for (const Row& row : rows) {
    EXPECT_GE(std::stoi(row.at("frames")), 1) << row.at("method");
    EXPECT_LE(std::stoi(row.at("frames")), 10) << row.at("method");
  }
  EXPECT_EQ(rows[1].at("covered_pct"), rows[4].at("covered_pct"));  // compute and cpu superquadrics
  // A total budget spent by the first count: its rows, none of the second's.
  r = tg::test::runBinary("bench scale --n 300,1000 --size 96 64 --pipelines compute --frames 1 "
                          "--total-budget 0.001 -o " + csv.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("the sweep's 0.001 s are spent"), std::string::npos) << r.err;
  rows = readCsv(csv);
  EXPECT_LT(rows.size(), 3u);
  for (const Row& row : rows) EXPECT_EQ(row.at("n"), "300");
  std::filesystem::remove_all(dir);
}

// Glyphs a few pixels wide: llvmpipe's profile runs the occlusion pre-pass
// for the superquadric row, and its -no-prepass twin draws the same pixels
// without it.
TEST(BenchScale, NoPrepassRowsSkipThePrepass) {
  const auto dir = tg::test::cliDir("bench_scale_prepass");
  const auto csv = dir / "scale.csv";
  const auto r = tg::test::runBinary("bench scale --n 2000 --size 320 240 --resolutions 4 --frames 1 -o " + csv.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  std::map<std::string, Row> byMethod;
  for (const Row& row : readCsv(csv)) byMethod[row.at("method")] = row;
  ASSERT_EQ(byMethod.count("raycast-superquadric-no-prepass"), 1u);
  EXPECT_EQ(byMethod["raycast-superquadric"].at("prepass"), "1");
  EXPECT_EQ(byMethod["raycast-superquadric-no-prepass"].at("prepass"), "0");
  EXPECT_EQ(byMethod["raycast-superquadric"].at("covered_pct"), byMethod["raycast-superquadric-no-prepass"].at("covered_pct"));
  std::filesystem::remove_all(dir);
}

// The carried executable runs the same sweep through EGL (Mesa surfaceless
// here): the same rows, and the same coverage figures, since both renderers
// are llvmpipe and the shapes do not depend on the platform.
TEST(GpuBench, RunsTheSameSweepThroughEgl) {
  const auto dir = tg::test::cliDir("gpubench");
  const auto viaEgl = dir / "egl.csv", viaOsmesa = dir / "osmesa.csv";
  auto r = tg::test::runBinary(kSweep + viaEgl.string(), dir, TG_GPUBENCH);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto egl = checkSweep(readCsv(viaEgl));
  r = tg::test::runBinary("bench scale " + kSweep + viaOsmesa.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(egl, checkSweep(readCsv(viaOsmesa)));
  tg::test::expectFailsCleanly("--backend osmesa -o " + viaEgl.string(), "only egl", viaEgl, dir, 1, TG_GPUBENCH);
  tg::test::expectFailsCleanly("--frames 0 -o " + viaEgl.string(), "--frames", viaEgl, dir, 1, TG_GPUBENCH);
  std::filesystem::remove_all(dir);
}

// A GPU run must never time the software renderer: with --require-gpu the
// sweep either fails cleanly (no GPU, as in CI) or names a hardware device.
TEST(GpuBench, RequireGpuNeverTimesSoftware) {
  const auto dir = tg::test::cliDir("gpubench_hw");
  const auto csv = dir / "hw.csv";
  std::filesystem::remove(csv);
  const auto r = tg::test::runBinary("--require-gpu --n 100 --size 64 64 --resolutions 4 --frames 1 -o " + csv.string(),
                                     dir, TG_GPUBENCH);
  if (r.code != 0) {
    EXPECT_NE(r.err.find("software"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(csv));
  } else {
    for (const Row& row : readCsv(csv)) EXPECT_EQ(row.at("device").find("llvmpipe"), std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

// The point of the executable: it runs where VTK, OpenImageIO, Teem and GLFW
// are absent, so it may need libEGL and the C library's parts alone.
TEST(GpuBench, NeedsOnlyEglAndTheCLibrary) {
  FILE* p = ::popen(("readelf -d " + std::string(TG_GPUBENCH)).c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string text;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p)) text += buf;
  ASSERT_EQ(::pclose(p), 0) << text;
  std::vector<std::string> needed;
  for (std::size_t at = text.find("(NEEDED)"); at != std::string::npos; at = text.find("(NEEDED)", at + 1)) {
    const std::size_t open = text.find('[', at), close = text.find(']', open);
    needed.push_back(text.substr(open + 1, close - open - 1));
  }
  ASSERT_FALSE(needed.empty()) << text;
  for (const std::string& lib : needed)
    EXPECT_TRUE(lib == "libEGL.so.1" || lib == "libc.so.6" || lib == "libm.so.6" || lib.rfind("ld-linux", 0) == 0)
        << "tensorglyph-gpubench needs " << lib;
}

}  // namespace
