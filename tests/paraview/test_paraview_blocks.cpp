// The ParaView plugin on composite (multiblock) inputs, and the load
// warnings it shares with the CLI. pvbatch under Xvfb, as
// test_paraview_plugin.cpp; skips, saying why, where the plugin was not built.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "paraview/paraview_run.h"

namespace {

using namespace tg::test::pv;

// The kitten has 14,961 points; --write-blocks puts the first 7,480 in block
// 0 (flat index 1: the root is 0) and the rest in block 1 (flat index 2).
constexpr std::uint32_t kFirstBlockPoints = 14961 / 2;

long glyphPixels(const Image& img) {
  long n = 0;
  for (int i = 0; i < img.width * img.height; ++i) n += covered(img, i, kBackground);
  return n;
}

// The kitten split into a two-block .vtm by the driver script.
fs::path writeBlocks(const fs::path& dir, const std::string& input = pvKitten(), const std::string& extra = "") {
  const fs::path vtm = dir / "blocks.vtm";
  const CmdResult w = runPvbatch("--input " + input + " --write-blocks " + vtm.string() + extra, dir);
  EXPECT_EQ(w.code, 0) << w.err;
  return vtm;
}

// GroupDatasets of the kitten (one block, as any multiblock filter output)
// draws the kitten's picture; it was refused with "apply Merge Blocks".
TEST_F(ParaViewPlugin, MultiblockInputIsDrawn) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path plain = dir / "plain.png", grouped = dir / "grouped.png";
  const CmdResult a = runPvbatch("--output " + plain.string() + " " + kCamera, dir);
  ASSERT_EQ(a.code, 0) << a.err;
  const CmdResult b = runPvbatch("--output " + grouped.string() + " " + kCamera + " --multiblock", dir);
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_EQ(b.err.find("Merge Blocks"), std::string::npos) << b.err;
  const Image x = readImage(plain), y = readImage(grouped);
  ASSERT_EQ(x.width, 400);
  ASSERT_EQ(y.width, x.width);
  ASSERT_GT(glyphPixels(x), 2000);
  EXPECT_EQ(differing(x, y, 0.0f), 0);
}

// A .vtm of two blocks draws every block: the picture is that of the blocks
// merged (ParaView's Merge Blocks, shown through the plugin), and that of the
// kitten itself, pixel for pixel (same points, tensors and sizing).
TEST_F(ParaViewPlugin, BlocksOfAVtmDrawAsTheMergedDataset) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path vtm = writeBlocks(dir);
  ASSERT_TRUE(fs::exists(vtm));
  const fs::path blocks = dir / "blocks.png", merged = dir / "merged.png", plain = dir / "plain.png";
  const CmdResult a = runPvbatch("--output " + blocks.string() + " " + kCamera + " --input " + vtm.string(), dir);
  ASSERT_EQ(a.code, 0) << a.err;
  const CmdResult b = runPvbatch(
    "--output " + merged.string() + " " + kCamera + " --input " + vtm.string() + " --merge-blocks", dir);
  ASSERT_EQ(b.code, 0) << b.err;
  const CmdResult c = runPvbatch("--output " + plain.string() + " " + kCamera, dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const Image x = readImage(blocks), y = readImage(merged), z = readImage(plain);
  ASSERT_EQ(x.width, 400);
  ASSERT_EQ(y.width, x.width);
  ASSERT_EQ(z.width, x.width);
  ASSERT_GT(glyphPixels(y), 2000);
  EXPECT_EQ(differing(x, y, 0.0f), 0);
  EXPECT_EQ(differing(x, z, 0.0f), 0);
}

// Under MPI ParaView's .vtm reader hands each rank some of the blocks: each
// rank draws its blocks and IceT composites by depth. Absolute scale (as
// ParaViewMpi: no data-dependent sizing); the tolerance is ParaViewMpi's.
TEST_F(ParaViewPlugin, BlocksUnderMpiEqualTheSerialPicture) {
  TG_SKIP_WITHOUT_PARAVIEW();
  if (std::system("command -v mpiexec >/dev/null 2>&1") != 0) GTEST_SKIP() << "mpiexec is not installed";
  const fs::path vtm = writeBlocks(dir);
  const std::string args = kCamera + " --input " + vtm.string() + " --scale-mode 0 --scale 0.0178";
  const fs::path serial = dir / "serial.png", parallel = dir / "parallel.png";
  const CmdResult one = runPvbatch("--output " + serial.string() + " " + args, dir);
  ASSERT_EQ(one.code, 0) << one.err;
  const CmdResult two = runPvbatch("--output " + parallel.string() + " " + args, dir, 2);
  ASSERT_EQ(two.code, 0) << two.err;
  const Image a = readImage(serial), b = readImage(parallel);
  ASSERT_EQ(a.width, 400);
  ASSERT_EQ(b.width, a.width);
  ASSERT_GT(glyphPixels(a), 2000);
  EXPECT_LE(differing(a, b, 1.0f / 255.0f), a.width * a.height / 1000);
}

// A block without the tensor array is skipped without a word, as ParaView's
// Tensor Glyph skips it; the other block is drawn. Absolute scale, so that
// the glyphs drawn are the full picture's: every pixel they cover is covered
// there, and the second block's glyphs leave many pixels uncovered.
TEST_F(ParaViewPlugin, BlocksWithoutTheTensorsAreSkipped) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const std::string args = kCamera + " --scale-mode 0 --scale 0.0178";
  const fs::path full = dir / "full.png", part = dir / "part.png";
  const CmdResult a = runPvbatch("--output " + full.string() + " " + args, dir);
  ASSERT_EQ(a.code, 0) << a.err;
  const fs::path vtm = writeBlocks(dir, pvKitten(), " --second-without-tensors");
  const CmdResult b = runPvbatch("--output " + part.string() + " " + args + " --input " + vtm.string(), dir);
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_EQ(b.err.find("prepareGlyphInput"), std::string::npos) << b.err;
  const Image x = readImage(full), y = readImage(part);
  ASSERT_EQ(x.width, 400);
  ASSERT_EQ(y.width, x.width);
  long outside = 0;
  for (int i = 0; i < y.width * y.height; ++i) outside += covered(y, i, kBackground) && !covered(x, i, kBackground);
  EXPECT_EQ(outside, 0);
  EXPECT_GT(glyphPixels(y), 1000);
  EXPECT_LT(glyphPixels(y), glyphPixels(x) - 1000);
}

// (flat index, point id) of a kitten point id in the two-block .vtm.
std::pair<long, long> inBlocks(std::uint32_t id) {
  return id < kFirstBlockPoints ? std::pair<long, long>{1, id} : std::pair<long, long>{2, id - kFirstBlockPoints};
}

// Selecting points on the glyphs of a composite input gives ParaView's
// composite ids: each glyph's block (flat index) and its point id within the
// block, as for any composite dataset (a CompositeDataIDSelectionSource). The
// CLI's id channel of the whole kitten says which glyph each pixel shows, as
// in SelectionReturnsTheGlyphsPointIds; its ids map to (block, id) by the
// split. The 3 x 3 rectangle selects that glyph's (block, id) alone; the
// 40 x 40 one exactly the glyphs shown there, from both blocks.
TEST_F(ParaViewPlugin, SelectionOnBlocksReturnsBlockAndPointIds) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path exr = dir / "cli.exr", pv = dir / "pv.png", sel = dir / "selection.txt";
  const CmdResult c = tg::test::runBinary("render " + kKitten + kPluginLook + " -o " + exr.string() + " " + kCamera, dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const Image img = readImage(exr);
  const std::vector<std::uint32_t> ids = readIds(exr, img);
  ASSERT_EQ(ids.size(), std::size_t(img.width) * img.height);
  const Picks picks = findPicks(ids, img);
  ASSERT_NE(picks.target, kNoGlyph) << "no glyph covers a 3 x 3 block";
  std::set<std::pair<long, long>> shown;
  for (std::uint32_t id : picks.shown) shown.insert(inBlocks(id));
  std::set<long> shownBlocks;
  for (const auto& s : shown) shownBlocks.insert(s.first);
  ASSERT_EQ(shownBlocks.size(), 2u) << "the centre block must show glyphs of both blocks";

  const fs::path vtm = writeBlocks(dir);
  const CmdResult r = runPvbatch("--output " + pv.string() + " " + kCamera + " --input " + vtm.string() +
                                   picks.inside.args() + picks.block.args() + " --selection-out " + sel.string(),
                                 dir);
  ASSERT_EQ(r.code, 0) << r.err;
  std::set<std::pair<long, long>> picked[2];
  std::ifstream in(sel);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string kind;
    long rect = -1, flat = -1, id = -1;
    s >> kind >> rect >> flat >> id;
    ASSERT_EQ(kind, "blockpoints") << "not a composite id: " << line;
    ASSERT_TRUE(rect == 0 || rect == 1) << line;
    picked[rect].insert({flat, id});
  }
  const std::set<std::pair<long, long>> target{inBlocks(picks.target)};
  EXPECT_EQ(picked[0], target);
  EXPECT_EQ(picked[1], shown);
}

// A composite input none of whose blocks has tensors says so once (not per
// block, not per render) and draws nothing.
TEST_F(ParaViewPlugin, BlocksWithoutTensorsAreSaidSoOnce) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path in = dir / "scalars.vtk", png = dir / "scalars.png";
  std::ofstream(in) << "# vtk DataFile Version 3.0\nscalars only\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
                       "0 0 0 1 0 0 0 1 0 1 1 0\nPOINT_DATA 4\nSCALARS fa float 1\nLOOKUP_TABLE default\n"
                       "0.1 0.5 0.9 0.3\n";
  const fs::path vtm = writeBlocks(dir, in.string());
  const CmdResult r = runPvbatch("--output " + png.string() + " --input " + vtm.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string said = "none of the 2 blocks with points has a point array of tensors";
  const std::size_t at = r.err.find(said);
  EXPECT_NE(at, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(said, at + 1), std::string::npos) << "said more than once: " << r.err;
}

// A legacy binary .vtk of points with 9-component tensors (big-endian
// doubles): `asymmetric` gives the finite ones off-diagonal parts that differ
// (the largest asymmetry 0.5) and adds a NaN and an overflowing tensor.
void writeTensorPoints(const fs::path& p, bool asymmetric) {
  std::vector<std::array<double, 9>> t;
  for (int k = 0; k < 4; ++k) {
    const double a = asymmetric ? 0.125 * (k + 1) : 0.0;  // asymmetry: 2a over max |sym| 2
    t.push_back({2.0, 0.3 + a, 0.1, 0.3 - a, 1.5, 0.2, 0.1, 0.2, 1.0});
  }
  if (asymmetric) {
    t.push_back({NAN, 0, 0, 0, 1, 0, 0, 0, 1});
    t.push_back({1e39, 0, 0, 0, 1e39, 0, 0, 0, 1e39});
  }
  std::ofstream f(p, std::ios::binary);
  auto put = [&](double v) {
    std::uint64_t u;
    std::memcpy(&u, &v, 8);
    for (int b = 7; b >= 0; --b) f.put(char((u >> (8 * b)) & 0xFF));
  };
  f << "# vtk DataFile Version 3.0\ntensors\nBINARY\nDATASET POLYDATA\nPOINTS " << t.size() << " double\n";
  for (std::size_t i = 0; i < t.size(); ++i) {
    put(double(i % 3));
    put(double(i / 3));
    put(0.0);
  }
  f << "\nPOINT_DATA " << t.size() << "\nTENSORS t double\n";
  for (const auto& m : t)
    for (double v : m) put(v);
  f << "\n";
}

// The CLI's load warnings for a file, without the "tensorglyph render: FILE: ".
std::vector<std::string> cliWarnings(const std::string& err, const fs::path& file) {
  std::vector<std::string> out;
  const std::string prefix = "tensorglyph render: " + file.string() + ": ";
  std::istringstream s(err);
  std::string line;
  while (std::getline(s, line))
    if (line.rfind(prefix, 0) == 0) out.push_back(line.substr(prefix.size()));
  return out;
}

// The plugin said what the CLI says of the same file, in its words, each
// once although the view rendered three times: the asymmetric tensors drawn
// symmetrised, the NaN and the overflowing tensor skipped.
TEST_F(ParaViewPlugin, LoadWarningsAreTheClis) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path in = dir / "asym.vtk", cliPng = dir / "cli.png", png = dir / "pv.png";
  writeTensorPoints(in, true);
  const CmdResult c = tg::test::runBinary("render " + in.string() + " -o " + cliPng.string(), dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const std::vector<std::string> cli = cliWarnings(c.err, in);
  ASSERT_EQ(cli.size(), 3u) << c.err;
  EXPECT_NE(cli[0].find("are asymmetric (max |D - D"), std::string::npos) << c.err;
  EXPECT_NE(cli[0].find("= 0.500000)"), std::string::npos) << c.err;
  const CmdResult r = runPvbatch("--output " + png.string() + " --input " + in.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const std::string& w : cli) {
    const std::string said = "prepareGlyphInput: array 't': " + w;
    const std::size_t at = r.err.find(said);
    EXPECT_NE(at, std::string::npos) << said << "\n" << r.err;
    EXPECT_EQ(r.err.find(said, at + 1), std::string::npos) << "said more than once: " << r.err;
  }
}

// Symmetric tensors (a small file, and the kitten) give no load warning.
TEST_F(ParaViewPlugin, SymmetricTensorsGiveNoWarning) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path in = dir / "sym.vtk", cliPng = dir / "cli.png", png = dir / "pv.png";
  writeTensorPoints(in, false);
  const CmdResult c = tg::test::runBinary("render " + in.string() + " -o " + cliPng.string(), dir);
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_TRUE(cliWarnings(c.err, in).empty()) << c.err;
  for (const std::string& input : {in.string(), pvKitten()}) {
    const CmdResult r = runPvbatch("--output " + png.string() + " --input " + input, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("asymmetric"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("prepareGlyphInput"), std::string::npos) << r.err;
  }
}

}  // namespace
