// The program cache (gl/program_cache.h) through the binary: a cold and a
// warm cache give the image of no cache, damaged or foreign entries are
// ignored (and written anew), and TG_NO_PROGRAM_CACHE=1 writes nothing. Each
// test has its own XDG_CACHE_HOME, so no result depends on the cache the
// machine already holds.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "cli/cli_run.h"

namespace fs = std::filesystem;
using tg::test::cliDir;
using tg::test::runBinary;
using tg::test::slurp;

namespace {

// A superquadric scene, so that the march's programs are cached too.
const std::string kScene = " --size 96 72 --glyph superquadric";

std::string withCache(const fs::path& xdg, bool on = true) {
  return std::string("env ") + (on ? "-u TG_NO_PROGRAM_CACHE" : "TG_NO_PROGRAM_CACHE=1") +
         " XDG_CACHE_HOME=" + xdg.string() + " " TG_BINARY;
}

fs::path render(const fs::path& d, const fs::path& xdg, const std::string& name, bool cacheOn = true) {
  const fs::path out = d / name;
  const auto r = runBinary("render -o " + out.string() + kScene, d, withCache(xdg, cacheOn));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "") << name;
  return out;
}

std::map<fs::path, std::string> entries(const fs::path& xdg) {
  std::map<fs::path, std::string> e;
  const fs::path dir = xdg / "tensorglyph" / "programs";
  if (fs::exists(dir))
    for (const auto& f : fs::directory_iterator(dir))
      e[f.path()] = fs::is_regular_file(f.path()) ? slurp(f.path()) : "(not a regular file)";
  return e;
}

void write(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace

TEST(ProgramCache, ColdAndWarmCachesGiveTheImageOfNoCache) {
  const fs::path d = cliDir("progcache_warm"), xdg = d / "xdg";
  fs::remove_all(xdg);
  const std::string none = slurp(render(d, d / "xdg-off", "none.png", false));
  EXPECT_FALSE(fs::exists(d / "xdg-off" / "tensorglyph"));
  ASSERT_GT(none.size(), 100u);
  EXPECT_EQ(slurp(render(d, xdg, "cold.png")), none);
  const auto written = entries(xdg);
  // The ellipsoid, march, lighting, culling and pyramid programs at least.
  EXPECT_GE(written.size(), 4u);
  EXPECT_EQ(slurp(render(d, xdg, "warm.png")), none);
  EXPECT_EQ(entries(xdg), written);  // a warm run rewrites nothing
}

TEST(ProgramCache, DamagedAndForeignEntriesAreIgnoredAndWrittenAnew) {
  const fs::path d = cliDir("progcache_damaged"), xdg = d / "xdg";
  fs::remove_all(xdg);
  const std::string reference = slurp(render(d, xdg, "reference.png"));
  const auto good = entries(xdg);
  ASSERT_GE(good.size(), 4u);
  std::vector<fs::path> paths;
  for (const auto& [p, bytes] : good) paths.push_back(p);
  // Each way an entry can be wrong, one per file (cycled): truncated, empty,
  // garbage, one byte of the binary flipped, one byte of the key flipped,
  // another program's whole valid entry (a foreign one), and a FIFO, which
  // must not block the reader.
  ASSERT_GE(paths.size(), 7u);
  for (std::size_t k = 0; k < paths.size(); ++k) {
    const std::string& bytes = good.at(paths[k]);
    std::string bad;
    if (k % 7 == 6) {
      fs::remove(paths[k]);
      ASSERT_EQ(::mkfifo(paths[k].c_str(), 0600), 0);
      continue;
    }
    switch (k % 7) {
      case 0: bad = bytes.substr(0, bytes.size() / 2); break;
      case 1: bad = ""; break;
      case 2: bad = std::string(bytes.size(), '\x5a'); break;
      case 3: bad = bytes; bad[bad.size() - 7] ^= 0x10; break;
      case 4: bad = bytes; bad[60] ^= 0x01; break;
      default: bad = good.at(paths[(k + 1) % paths.size()]); break;
    }
    write(paths[k], bad);
  }
  EXPECT_EQ(slurp(render(d, xdg, "damaged.png")), reference);
  // Every damaged entry was replaced by a good one, which the next run uses.
  EXPECT_EQ(entries(xdg), good);
  EXPECT_EQ(slurp(render(d, xdg, "again.png")), reference);
}

TEST(ProgramCache, AnUnwritableCacheDirectoryIsNoError) {
  const fs::path d = cliDir("progcache_unwritable"), xdg = d / "xdg";
  fs::remove_all(xdg);
  fs::create_directories(xdg);
  write(xdg / "tensorglyph", "a file where the cache's directory would be");
  const std::string none = slurp(render(d, d / "xdg-off", "none.png", false));
  EXPECT_EQ(slurp(render(d, xdg, "blocked.png")), none);
  EXPECT_TRUE(fs::is_regular_file(xdg / "tensorglyph"));
}
