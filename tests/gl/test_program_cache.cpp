// Tier 3: the program cache's entries (gl/program_cache.h). Any damage is
// caught before the driver sees it, and a well-formed entry the driver
// refuses leaves no GL error behind: the program is then compiled as
// without a cache. The tests give the cache a directory of their own.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "gl/program.h"
#include "gl/program_cache.h"
#include "render_fixture.h"

using namespace tg;
using test::GlFixture;

namespace {

// The environment of one test: XDG_CACHE_HOME in a scratch directory and the
// cache switched on, restored afterwards.
class CacheEnvironment {
 public:
  explicit CacheEnvironment(const std::filesystem::path& xdg) {
    save("XDG_CACHE_HOME", xdg_);
    save("TG_NO_PROGRAM_CACHE", off_);
    std::filesystem::remove_all(xdg);
    ::setenv("XDG_CACHE_HOME", xdg.c_str(), 1);
    ::unsetenv("TG_NO_PROGRAM_CACHE");
  }
  ~CacheEnvironment() {
    restore("XDG_CACHE_HOME", xdg_);
    restore("TG_NO_PROGRAM_CACHE", off_);
  }

 private:
  static void save(const char* name, std::optional<std::string>& v) {
    if (const char* s = std::getenv(name)) v = s;
  }
  static void restore(const char* name, const std::optional<std::string>& v) {
    if (v) ::setenv(name, v->c_str(), 1);
    else ::unsetenv(name);
  }
  std::optional<std::string> xdg_, off_;
};

std::string key(const gl::ProgramCache& cache, const gl::ShaderLibrary& lib) {
  return cache.key({{GL_VERTEX_SHADER, lib.compose("fullscreen.vert").text},
                    {GL_FRAGMENT_SHADER, lib.compose("lighting.frag").text}});
}

}  // namespace

TEST(ProgramCacheEntry, DecodesOnlyAnIntactEntryOfItsOwnKey) {
  const std::string k = "driver\nsource";
  const gl::ProgramCache::Binary b{0x1234, {'b', 'i', 'n', 'a', 'r', 'y'}};
  const std::string e = gl::ProgramCache::encodeEntry(k, b);
  const auto back = gl::ProgramCache::decodeEntry(e, k);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->format, b.format);
  EXPECT_EQ(back->bytes, b.bytes);
  EXPECT_FALSE(gl::ProgramCache::decodeEntry(e, k + " "));
  for (std::size_t n = 0; n < e.size(); ++n) EXPECT_FALSE(gl::ProgramCache::decodeEntry(e.substr(0, n), k)) << n;
  EXPECT_FALSE(gl::ProgramCache::decodeEntry(e + "x", k));
  for (std::size_t i = 0; i < e.size(); ++i) {
    std::string bad = e;
    bad[i] ^= 0x04;
    EXPECT_FALSE(gl::ProgramCache::decodeEntry(bad, k)) << "byte " << i;
  }
}

TEST_F(GlFixture, AnEntryTheDriverRefusesIsIgnoredAndReplaced) {
  ctx_->makeCurrent();
  const gl::Api& api = ctx_->api();
  const CacheEnvironment env(std::filesystem::temp_directory_path() / ("tg_progcache_" + std::to_string(::getpid())));
  const gl::ProgramCache cache(api);
  if (!cache.enabled()) GTEST_SKIP() << "the driver offers no program binary format (Mesa's disk cache is off)";
  const std::string k = key(cache, *lib_);
  // A program, linked from source, fills the cache; its entry loads.
  const auto build = [&] {
    return gl::Program(api, *lib_, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "lighting.frag"}});
  };
  { const gl::Program p = build(); }
  std::filesystem::path entry;
  for (const auto& f : std::filesystem::directory_iterator(cache.directory())) entry = f.path();
  ASSERT_FALSE(entry.empty());
  std::ifstream in(entry, std::ios::binary);
  const std::string good{std::istreambuf_iterator<char>(in), {}};
  auto decoded = gl::ProgramCache::decodeEntry(good, k);
  ASSERT_TRUE(decoded.has_value());
  GLuint id = api.CreateProgram();
  EXPECT_TRUE(cache.load(id, k));
  api.DeleteProgram(id);
  // The same entry, well formed and checksummed, with a binary the driver
  // cannot use: refused without a GL error, and replaced by the next build.
  for (char& c : decoded->bytes) c = char(c * 7 + 3);
  std::ofstream(entry, std::ios::binary | std::ios::trunc) << gl::ProgramCache::encodeEntry(k, *decoded);
  id = api.CreateProgram();
  EXPECT_FALSE(cache.load(id, k));
  EXPECT_EQ(api.GetError(), GLenum(GL_NO_ERROR));
  GLint linked = 1;
  api.GetProgramiv(id, GL_LINK_STATUS, &linked);
  EXPECT_EQ(linked, GL_FALSE);
  api.DeleteProgram(id);
  { const gl::Program p = build(); }
  std::ifstream again(entry, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(again), {}), good);
  std::filesystem::remove_all(std::filesystem::path(cache.directory()).parent_path().parent_path());
}
