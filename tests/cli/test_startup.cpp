// What the binary loads (issue 17, start-up): OpenImageIO and Mesa only when
// a command needs them, and a clear failure when the OpenImageIO module is
// missing. The dynamic loader's own trace (LD_DEBUG=files) is the witness.
#include <filesystem>
#include <string>

#include "cli/cli_run.h"

namespace fs = std::filesystem;
using tg::test::cliDir;
using tg::test::runBinary;

namespace {

// The libraries the loader opened while running `args`, as it reports them.
tg::test::CmdResult traced(const std::string& args, const fs::path& scratch, const std::string& binary = TG_BINARY) {
  return runBinary(args, scratch, "env LD_DEBUG=files " + binary);
}

bool opened(const tg::test::CmdResult& r, const std::string& library) {
  return r.err.find("file=" + library) != std::string::npos;
}

}  // namespace

TEST(Startup, HelpLoadsNeitherImageLibraryNorMesa) {
  const fs::path d = cliDir("startup_help");
  const auto r = traced("--help", d);
  ASSERT_EQ(r.code, 0) << r.err.substr(0, 2000);
  EXPECT_NE(r.out.find("render"), std::string::npos);
  // The trace lists libc, so an empty trace cannot pass for a lean one.
  EXPECT_TRUE(opened(r, "libc.so.6"));
  EXPECT_FALSE(opened(r, "libOpenImageIO.so"));
  EXPECT_FALSE(opened(r, "libOSMesa.so"));
  EXPECT_FALSE(opened(r, "libLLVM"));
}

TEST(Startup, PngRenderLoadsMesaButNotOpenImageIO) {
  const fs::path d = cliDir("startup_png");
  const auto r = traced("render -o " + (d / "a.png").string() + " --size 64 48", d);
  ASSERT_EQ(r.code, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
  EXPECT_TRUE(fs::file_size(d / "a.png") > 100);
  EXPECT_TRUE(opened(r, "libOSMesa.so.8"));
  EXPECT_FALSE(opened(r, "libOpenImageIO.so"));
}

TEST(Startup, ExrRenderLoadsTheOpenImageIOModule) {
  const fs::path d = cliDir("startup_exr");
  const auto r = traced("render -o " + (d / "a.exr").string() + " --size 64 48", d);
  ASSERT_EQ(r.code, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
  EXPECT_TRUE(fs::exists(d / "a.exr"));
  EXPECT_NE(r.err.find("tensorglyph-oiio.so"), std::string::npos);
  EXPECT_TRUE(opened(r, "libOpenImageIO.so.2.4"));
}

// A binary installed without its module still writes PNG, and refuses the
// formats that need the module in one line, before rendering anything.
TEST(Startup, WithoutTheModuleOnlyItsFormatsFail) {
  const fs::path d = cliDir("startup_nomodule");
  const fs::path lone = d / "tensorglyph";
  fs::copy_file(TG_BINARY, lone, fs::copy_options::overwrite_existing);
  ASSERT_FALSE(fs::exists(d / "tensorglyph-oiio.so"));
  const auto png = runBinary("render -o " + (d / "a.png").string() + " --size 64 48", d, lone.string());
  EXPECT_EQ(png.code, 0) << png.err;
  EXPECT_TRUE(fs::exists(d / "a.png"));
  tg::test::expectFailsCleanly("render -o " + (d / "a.exr").string() + " --size 64 48",
                               "needs OpenImageIO, through the module " + (d / "tensorglyph-oiio.so").string(),
                               d / "a.exr", d, 1, lone.string());
}
