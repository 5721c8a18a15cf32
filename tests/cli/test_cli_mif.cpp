// Tier 2: MRtrix images through the real binary: info and render read them,
// a .mif mask selects, and a bad one fails cleanly with no image left.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/cli_run.h"
#include "io/mif_fixture.h"

namespace fs = std::filesystem;

namespace {

fs::path dir() { return tg::test::cliDir("cli_mif"); }

// A 4x3x2 grid of prolate tensors in a rotated frame, stored as MRtrix's
// mrconvert stores a det > 0 NIfTI: x descending, one volume per component.
tg::test::MifFixture prolate() {
  tg::test::MifFixture fx;
  fx.dims[0] = 4, fx.dims[1] = 3, fx.dims[2] = 2;
  fx.layout = {"-0", "+1", "+2", "+3"};
  fx.transform = {{0, -1, 0, 5}, {1, 0, 0, -7}, {0, 0, 1, 2.5}};
  fx.mrtrix.assign(fx.voxels(), {3e-3, 1e-3, 1e-3, 2e-4, 0, 0});
  return fx;
}

}  // namespace

TEST(CliMif, InfoAndRenderReadAnMrtrixImage) {
  const fs::path in = dir() / "tensors.mif", out = dir() / "tensors.png";
  tg::test::writeMif(in, prolate());
  const tg::test::CmdResult info = tg::test::runBinary("info " + in.string(), dir());
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("dataset: MRtrix image, 4x3x2x6, Float32LE, layout -0,+1,+2,+3"), std::string::npos)
      << info.out;
  EXPECT_NE(info.out.find("24 drawn"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("positive semi-definite: 24"), std::string::npos) << info.out;
  // Column 0 of the grid is the transform's first column: +y.
  EXPECT_NE(info.out.find("directions (columns): [0 1 0] [-1 0 0] [0 0 1]"), std::string::npos) << info.out;

  fs::remove(out);
  const tg::test::CmdResult r = tg::test::runBinary("render " + in.string() + " -o " + out.string() + " --size 96 64",
                                                    dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out));
}

TEST(CliMif, MrtrixMaskSelects) {
  const fs::path in = dir() / "masked.mif";
  tg::test::writeMif(in, prolate());
  // Keeps the voxels with k = 1, stored k fastest.
  std::string raw(24, '\0');
  for (int v = 12; v < 24; ++v) raw[std::size_t(v / 4 % 3 * 2 + v % 4 * 6 + v / 12)] = 1;
  std::string header = "mrtrix image\ndim: 4,3,2\nvox: 1,1,1\nlayout: +2,+1,+0\ndatatype: UInt8\nfile: . 96\nEND\n";
  header.resize(96, '\0');
  std::ofstream(dir() / "mask.mif", std::ios::binary) << header << raw;
  const tg::test::CmdResult r = tg::test::runBinary("info " + in.string() + " --mask " + (dir() / "mask.mif").string(),
                                                    dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("24 total, 12 masked"), std::string::npos) << r.out;
}

TEST(CliMif, BadMrtrixImageFailsCleanly) {
  const fs::path in = dir() / "bad.mif", out = dir() / "bad.png";
  tg::test::MifFixture fx = prolate();
  fx.extra = "dim: 4,3,2,6\n";  // a second dim
  tg::test::writeMif(in, fx);
  tg::test::expectFailsCleanly("render " + in.string() + " -o " + out.string(),
                               "readMif: " + in.string() + ": key \"dim\" appears twice", out, dir(), 1);
  const tg::test::CmdResult r = tg::test::runBinary("info " + in.string(), dir());
  EXPECT_EQ(r.code, 1);
}
