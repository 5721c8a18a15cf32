// Tier 2: --pipeline auto through the real binary, with calibration caches
// written here (TG_CACHE_DIR), so that the choice is fixed by the table:
// each table's choice is the path named, draws that path's picture, and
// --verbose says why.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using tg::test::CmdResult;

fs::path dir() { return tg::test::cliDir("pipeline"); }

CmdResult run(const std::string& args) { return tg::test::runBinary(args, dir()); }

std::string slurpFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The key this machine's renderer gets, from a run that calibrates into `cache`.
std::string keyFromCalibration(const fs::path& cache) {
  const std::string text = slurpFile(cache / "pipelines.tsv");
  const std::size_t row = text.find('\n', text.find('\n') + 1) + 1;
  return text.substr(row, text.find('\t', row) - row);
}

void writeTable(const fs::path& cache, const std::string& key, double rasterGlyphUs, double cpuGlyphUs,
                double computeGlyphUs = 100.0) {
  fs::create_directories(cache);
  std::ofstream f(cache / "pipelines.tsv", std::ios::trunc);
  f << "# tensorglyph --pipeline auto calibration 1\n"
    << "key\tpath\tclass\tfixed_ms\tglyph_us\tmegapixel_ms\n";
  for (const char* cls : {"closed-form", "march"})
    f << key << "\traster\t" << cls << "\t1\t" << rasterGlyphUs << "\t10\n"
      << key << "\tcpu\t" << cls << "\t1\t" << cpuGlyphUs << "\t10\n"
      << key << "\tcompute\t" << cls << "\t1\t" << computeGlyphUs << "\t10\n";
}

struct CacheDir {
  explicit CacheDir(const fs::path& p) : path(p) {
    fs::remove_all(p);
    ::setenv("TG_CACHE_DIR", p.c_str(), 1);
  }
  ~CacheDir() { ::unsetenv("TG_CACHE_DIR"); }
  fs::path path;
};

}  // namespace

TEST(PipelineCli, AutoTakesThePathItsTablePredictsFastest) {
  const CacheDir cache(dir() / "cache");
  const std::string base = " --size 160 120 --no-legend --verbose";
  const fs::path out = dir() / "auto.png", cpu = dir() / "cpu.png", raster = dir() / "raster.png",
                 compute = dir() / "compute.png";
  // No table yet: measured once, kept, and said so.
  const CmdResult first = run("render -o " + out.string() + base + " --pipeline auto");
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_NE(first.err.find("--pipeline auto: measured the glyph paths on this renderer in "), std::string::npos) << first.err;
  EXPECT_NE(first.err.find(", kept in " + (cache.path / "pipelines.tsv").string() + "\n"), std::string::npos) << first.err;
  const std::string key = keyFromCalibration(cache.path);
  ASSERT_NE(key.find("cores | LP_NUM_THREADS"), std::string::npos) << key;
  const CmdResult again = run("render -o " + out.string() + base + " --pipeline auto");
  EXPECT_EQ(again.err.find("measured"), std::string::npos) << again.err;

  ASSERT_EQ(run("render -o " + cpu.string() + base + " --pipeline cpu").code, 0);
  ASSERT_EQ(run("render -o " + raster.string() + base + " --pipeline raster").code, 0);
  ASSERT_EQ(run("render -o " + compute.string() + base + " --pipeline compute").code, 0);
  for (const auto& [rasterUs, cpuUs, computeUs, want] :
       {std::tuple{10.0, 1.0, 20.0, "cpu"}, std::tuple{1.0, 10.0, 20.0, "raster"}, std::tuple{10.0, 20.0, 1.0, "compute"}}) {
    writeTable(cache.path, key, rasterUs, cpuUs, computeUs);
    const CmdResult r = run("render -o " + out.string() + base + " --pipeline auto");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find(std::string("glyph path: ") + want + " (--pipeline auto: predicted"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("measured"), std::string::npos) << r.err;
    const std::string w = want;
    EXPECT_EQ(slurpFile(out), slurpFile(w == "cpu" ? cpu : w == "raster" ? raster : compute)) << want;
  }
  // Another renderer's rows are no answer for this one: measured, and both kept.
  writeTable(cache.path, "some GPU | 4.6 | 64 cores | LP_NUM_THREADS unset", 10.0, 1.0);
  const CmdResult other = run("render -o " + out.string() + base + " --pipeline auto");
  ASSERT_EQ(other.code, 0) << other.err;
  EXPECT_NE(other.err.find("measured"), std::string::npos) << other.err;
  const std::string kept = slurpFile(cache.path / "pipelines.tsv");
  EXPECT_NE(kept.find("some GPU"), std::string::npos);
  EXPECT_NE(kept.find(key), std::string::npos);
}

TEST(PipelineCli, KindsOnOnePathNeedNoTableAndBadCachesAreMeasuredAgain) {
  const CacheDir cache(dir() / "cache-kinds");
  const fs::path out = dir() / "kinds.png";
  // Blobs are drawn by the cpu path alone, a tessellated baseline by the raster path: nothing to measure.
  const std::string small = "render -o " + out.string() + " --size 96 72 --verbose --pipeline auto";
  const CmdResult blob = run(small + " --glyph blob");
  ASSERT_EQ(blob.code, 0) << blob.err;
  EXPECT_NE(blob.err.find("glyph path: cpu (--pipeline auto: the only path that draws blob glyphs here)"), std::string::npos)
      << blob.err;
  const CmdResult mesh = run(small + " --glyph superquadric --tessellate 8");
  ASSERT_EQ(mesh.code, 0) << mesh.err;
  EXPECT_NE(mesh.err.find("glyph path: raster (--pipeline auto: --tessellate draws on the raster path)"), std::string::npos)
      << mesh.err;
  EXPECT_FALSE(fs::exists(cache.path / "pipelines.tsv"));
  // A cache that is not one: one line names it and the problem, and the paths are measured again.
  fs::create_directories(cache.path);
  std::ofstream(cache.path / "pipelines.tsv") << "not a table\n";
  const CmdResult r = run("render -o " + out.string() + " --size 96 72 --pipeline auto");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("--pipeline auto: " + (cache.path / "pipelines.tsv").string() +
                       ":1: is not a tensorglyph calibration cache"),
            std::string::npos)
      << r.err;
  // One line says it all: what was wrong, what was measured, where it is kept.
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(slurpFile(cache.path / "pipelines.tsv").rfind("# tensorglyph --pipeline auto calibration 1\n", 0), 0u);
  const CmdResult bad = run("render -o " + out.string() + " --pipeline fastest");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--pipeline: unknown glyph path \"fastest\"; choose raster, cpu, compute or auto"), std::string::npos)
      << bad.err;
}

// The compute path's visibility buffer (8 bytes a pixel) is one storage
// block; llvmpipe's holds 2^27 bytes, so that 4200x4200 (141 MB) and a
// shadow map of 8192 texels a side (537 MB) are refused naming the option,
// with no output, where 4096x4096 would fit.
TEST(PipelineCli, ComputeRefusesAVisibilityBufferPastOneStorageBlock) {
  const fs::path out = dir() / "big.png";
  tg::test::expectFailsCleanly("render --pipeline compute --size 4200 4200 -o " + out.string(),
                               "visibility buffer for 4200x4200 is 141120000 bytes, more than one storage block holds (",
                               out, dir(), 1);
  const CmdResult r = run("render --pipeline compute --size 4200 4200 -o " + out.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE); use a smaller --size or --pipeline raster"), std::string::npos) << r.err;
  tg::test::expectFailsCleanly("render --pipeline compute --size 64 48 --shadows --shadow-map-size 8192 -o " + out.string(),
                               "use a smaller --shadow-map-size or --pipeline raster", out, dir(), 1);
}
