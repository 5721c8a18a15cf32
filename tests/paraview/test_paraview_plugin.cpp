// The ParaView plugin (plugins/paraview) in pvbatch under Xvfb: its picture
// against the CLI's, its depth against a ParaView slice, and MPI runs against
// the serial one. Skips, saying why, where the plugin was not built.
#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "paraview/paraview_run.h"

namespace {

using namespace tg::test::pv;

// The same renderer, field, sizing and camera: the plugin's picture is the
// CLI's. Both draw through Mesa's llvmpipe with the same shaders, and the
// composite copies colour unchanged, so the tolerance is one 8-bit step on at
// most 0.1% of the pixels (measured: no pixel differs). FXAA is off: it is
// ParaView's post-process, not part of the glyphs.
TEST_F(ParaViewPlugin, PictureMatchesTheCli) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path cli = dir / "cli.png", pv = dir / "pv.png";
  const CmdResult c = tg::test::runBinary("render " + kKitten + kPluginLook + " -o " + cli.string() + " " + kCamera, dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const CmdResult r = runPvbatch("--output " + pv.string() + " " + kCamera, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const Image a = readImage(cli), b = readImage(pv);
  ASSERT_EQ(a.width, 400);
  ASSERT_EQ(b.width, a.width);
  ASSERT_EQ(b.height, a.height);
  long glyphPixels = 0;
  for (int i = 0; i < a.width * a.height; ++i) glyphPixels += covered(a, i, kBackground);
  ASSERT_GT(glyphPixels, 2000) << "the view must show many glyphs for the comparison to mean anything";
  EXPECT_LE(differing(a, b, 1.0f / 255.0f), a.width * a.height / 1000);
}

// The tensors as cell data, picked from Python (the property's list offers
// point arrays only): one tuple per cell, so read per point they were other
// cells' tensors drawn at the points, without a word. The representation
// must say so and draw nothing.
TEST_F(ParaViewPlugin, CellTensorsAreRefusedNotReadPerPoint) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path pv = dir / "pv.png";
  const CmdResult r = runPvbatch("--output " + pv.string() + " " + kCamera + " --cell-tensors", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("the tensors must be point data"), std::string::npos) << r.err;
  const Image b = readImage(pv);
  ASSERT_EQ(b.width, 400);
  long glyphPixels = 0;
  for (int i = 0; i < b.width * b.height; ++i) glyphPixels += covered(b, i, kBackground);
  EXPECT_EQ(glyphPixels, 0);
}

// The kitten's tensors (9 components, exactly symmetric) given as 6 in VTK's
// symmetric order XX YY ZZ XY YZ XZ draw the same picture: the 6-component
// path, which the 9-component kitten never takes, reads VTK's order.
TEST_F(ParaViewPlugin, SixComponentTensorsDrawAsNine) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path nine = dir / "nine.png", six = dir / "six.png";
  const CmdResult a = runPvbatch("--output " + nine.string() + " " + kCamera, dir);
  ASSERT_EQ(a.code, 0) << a.err;
  const CmdResult b = runPvbatch("--output " + six.string() + " " + kCamera + " --as-six", dir);
  ASSERT_EQ(b.code, 0) << b.err;
  const Image x = readImage(nine), y = readImage(six);
  ASSERT_EQ(x.width, 400);
  ASSERT_EQ(y.width, x.width);
  long glyphPixels = 0;
  for (int i = 0; i < x.width * x.height; ++i) glyphPixels += covered(x, i, kBackground);
  ASSERT_GT(glyphPixels, 2000);
  EXPECT_EQ(differing(x, y, 0.0f), 0);
}

// vtkSetClampMacro stores a NaN (no comparison with it is true): a NaN
// Gamma or ScaleFactor set from Python drew another picture. It is ignored,
// so the picture is the one with the values kept (the defaults, 3 and 1).
TEST_F(ParaViewPlugin, NaNGammaAndScaleFactorAreIgnored) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path plain = dir / "plain.png", nan = dir / "nan.png";
  const CmdResult a = runPvbatch("--output " + plain.string() + " " + kCamera, dir);
  ASSERT_EQ(a.code, 0) << a.err;
  const CmdResult b = runPvbatch("--output " + nan.string() + " " + kCamera + " --gamma nan --scale nan", dir);
  ASSERT_EQ(b.code, 0) << b.err;
  const Image x = readImage(plain), y = readImage(nan);
  ASSERT_EQ(y.width, x.width);
  long glyphPixels = 0;
  for (int i = 0; i < x.width * x.height; ++i) glyphPixels += covered(x, i, kBackground);
  ASSERT_GT(glyphPixels, 2000);
  EXPECT_EQ(differing(x, y, 0.0f), 0);
}

// Points whose tensors have NaN are left out, as the CLI leaves them out,
// and said so once, in the CLI's words: 14,961 points, every 10th one NaN.
TEST_F(ParaViewPlugin, SkippedNaNTensorsAreReported) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path pv = dir / "pv.png";
  const CmdResult r = runPvbatch("--output " + pv.string() + " " + kCamera + " --nan-every 10", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string said = "prepareGlyphInput: array 'stress': skipped 1497 tensors with NaN/Inf components";
  const std::size_t at = r.err.find(said);
  EXPECT_NE(at, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(said, at + 1), std::string::npos) << "said more than once: " << r.err;
  const Image b = readImage(pv);
  ASSERT_EQ(b.width, 400);
  long glyphPixels = 0;
  for (int i = 0; i < b.width * b.height; ++i) glyphPixels += covered(b, i, kBackground);
  EXPECT_GT(glyphPixels, 2000) << "the other points must still be drawn";
}

// A ParaView slice through the kitten, facing the camera at the look-at
// point, so that its depth along the view axis is |eye - look-at| at every
// pixel. Where a glyph and the slice cover the same pixel, the CLI's depth
// channel (EXR Z, same camera) says which is nearer, and the mixed picture
// must show that one: the glyph's colour (as drawn alone) or the slice's (as
// drawn alone). Pixels within 1% of the slice's depth are not judged.
TEST_F(ParaViewPlugin, GlyphsMixWithASliceByDepth) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const double eye[3] = {40, 70, 170}, at[3] = {-1.5, 41.8, 5.6};
  const double n[3] = {eye[0] - at[0], eye[1] - at[1], eye[2] - at[2]};
  const double sliceDepth = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const std::string slice = " --slice-origin -1.5 41.8 5.6 --slice-normal " + std::to_string(n[0]) + " " +
                            std::to_string(n[1]) + " " + std::to_string(n[2]);
  const fs::path exr = dir / "cli.exr", glyphs = dir / "glyphs.png", sliceOnly = dir / "slice.png",
                 mixed = dir / "mixed.png";
  const CmdResult c = tg::test::runBinary("render " + kKitten + kPluginLook + " -o " + exr.string() + " " + kCamera, dir);
  ASSERT_EQ(c.code, 0) << c.err;
  for (const auto& [out, extra] : {std::pair{glyphs, std::string()}, std::pair{sliceOnly, slice + " --no-glyphs"},
                                   std::pair{mixed, slice}}) {
    const CmdResult r = runPvbatch("--output " + out.string() + " " + kCamera + extra, dir);
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const Image depth = readImage(exr), g = readImage(glyphs), s = readImage(sliceOnly), m = readImage(mixed);
  ASSERT_GE(depth.channels, 5);
  ASSERT_EQ(g.width, depth.width);
  ASSERT_EQ(s.width, depth.width);
  ASSERT_EQ(m.width, depth.width);
  long front = 0, behind = 0, wrongFront = 0, wrongBehind = 0;
  for (int i = 0; i < depth.width * depth.height; ++i) {
    const float z = depth.at(i)[4];
    if (!std::isfinite(z) || !covered(s, i, kBackground)) continue;
    auto same = [&](const Image& want) {
      for (int k = 0; k < 3; ++k)
        if (std::abs(m.at(i)[k] - want.at(i)[k]) > 1.0f / 255.0f) return false;
      return true;
    };
    if (z < 0.99 * sliceDepth) {
      ++front;
      wrongFront += !same(g);
    } else if (z > 1.01 * sliceDepth) {
      ++behind;
      wrongBehind += !same(s);
    }
  }
  ASSERT_GT(front, 200) << "glyphs in front of the slice";
  ASSERT_GT(behind, 200) << "glyphs behind the slice";
  EXPECT_LE(wrongFront, front / 100) << "glyphs in front of the slice hidden by it";
  EXPECT_LE(wrongBehind, behind / 100) << "glyphs behind the slice drawn over it";
}

// K ranks (RedistributeDataSet spreads the kitten over them) against one
// process without MPI: each rank draws its glyphs and IceT composites by
// depth. Every scale mode: in the spacing and max modes the size comes from
// the whole dataset's magnitudes and sample spacing, which the ranks reduce
// (global_sample.h; before, spacing mode drew 10,422 glyph pixels serial,
// 9,994 on 2 ranks and 10,560 on 4). Ranks share boundary points, whose
// duplicate glyphs coincide. Tolerance: one 8-bit step on 0.1% of the pixels
// (measured: none).
class ParaViewMpi : public ParaViewPlugin, public ::testing::WithParamInterface<std::tuple<int, int>> {};

TEST_P(ParaViewMpi, PictureEqualsTheSerialOne) {
  TG_SKIP_WITHOUT_PARAVIEW();
  if (std::system("command -v mpiexec >/dev/null 2>&1") != 0) GTEST_SKIP() << "mpiexec is not installed";
  const auto [mode, ranks] = GetParam();
  // Max mode: the largest glyph 20 spacings across (the default clamp then
  // caps it at 2), so that the typical one covers pixels.
  const std::string sizing = mode == 0   ? " --scale-mode 0 --scale 0.0178"
                             : mode == 1 ? " --scale-mode 1 --scale 20"
                                         : " --scale-mode 2";
  const std::string args = kCamera + " --redistribute" + sizing;
  const fs::path serial = dir / "serial.png", parallel = dir / "parallel.png";
  const CmdResult one = runPvbatch("--output " + serial.string() + " " + args, dir);
  ASSERT_EQ(one.code, 0) << one.err;
  const CmdResult k = runPvbatch("--output " + parallel.string() + " " + args, dir, ranks);
  ASSERT_EQ(k.code, 0) << k.err;
  const Image a = readImage(serial), b = readImage(parallel);
  ASSERT_EQ(a.width, 400);
  ASSERT_EQ(b.width, a.width);
  long glyphPixels = 0, parallelPixels = 0;
  for (int i = 0; i < a.width * a.height; ++i) {
    glyphPixels += covered(a, i, kBackground);
    parallelPixels += covered(b, i, kBackground);
  }
  ASSERT_GT(glyphPixels, 2000);
  EXPECT_EQ(parallelPixels, glyphPixels);
  EXPECT_LE(differing(a, b, 1.0f / 255.0f), a.width * a.height / 1000);
}

// (scale mode, ranks): absolute, spacing (the default) on 1, 2 and 4 ranks, max.
INSTANTIATE_TEST_SUITE_P(Ranks, ParaViewMpi,
                         ::testing::Values(std::tuple{0, 2}, std::tuple{0, 4}, std::tuple{2, 1}, std::tuple{2, 2},
                                           std::tuple{2, 4}, std::tuple{1, 4}));


// ParaView's surface point selection (SelectSurfacePoints, what "Select
// Points On" and hovering do) over the glyphs returns the glyphs' input
// point ids. The CLI's id channel (same field and camera, and the two
// pictures are equal pixel for pixel) says which glyph each pixel shows:
// a 3 x 3 rectangle inside one glyph selects exactly that glyph's point,
// not a glyph far away; a 40 x 40 rectangle selects exactly the glyphs the
// CLI shows in it. Glyphs have no cells: a cell selection there is empty.
TEST_F(ParaViewPlugin, SelectionReturnsTheGlyphsPointIds) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path exr = dir / "cli.exr", pv = dir / "pv.png", sel = dir / "selection.txt";
  const CmdResult c = tg::test::runBinary("render " + kKitten + kPluginLook + " -o " + exr.string() + " " + kCamera, dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const Image img = readImage(exr);
  const std::vector<std::uint32_t> ids = readIds(exr, img);
  ASSERT_EQ(ids.size(), std::size_t(img.width) * img.height);
  const Picks picks = findPicks(ids, img);
  ASSERT_GT(picks.distinct, 100u);
  ASSERT_NE(picks.target, kNoGlyph) << "no glyph covers a 3 x 3 block";
  ASSERT_GT(picks.farthest, 100.0);
  ASSERT_GT(picks.shown.size(), 10u) << "the centre block must show many glyphs";
  const std::uint32_t target = picks.target, far = picks.far;
  const Rect inside = picks.inside, block = picks.block;
  const std::set<std::uint32_t>& shown = picks.shown;

  std::string cells = block.args();
  cells.replace(0, 9, " --select-cells");
  const CmdResult r = runPvbatch("--output " + pv.string() + " " + kCamera + inside.args() + block.args() + cells +
                                     " --selection-out " + sel.string(),
                                 dir);
  ASSERT_EQ(r.code, 0) << r.err;
  std::set<std::uint32_t> picked[2];
  long cellsPicked = 0;
  std::ifstream in(sel);
  std::string kind;
  int rect = 0;
  long id = 0;
  while (in >> kind >> rect >> id) {
    ASSERT_GE(id, 0);
    if (kind == "cells") {
      ++cellsPicked;
      continue;
    }
    ASSERT_EQ(kind, "points");
    ASSERT_TRUE(rect == 0 || rect == 1);
    picked[rect].insert(std::uint32_t(id));
  }
  EXPECT_EQ(cellsPicked, 0);
  EXPECT_TRUE(picked[0].count(target)) << "glyph " << target << " not selected";
  EXPECT_FALSE(picked[0].count(far)) << "far glyph " << far << " selected";
  EXPECT_EQ(picked[0], std::set<std::uint32_t>{target});
  EXPECT_EQ(picked[1], shown);
}

std::map<std::string, std::vector<double>> readLegend(const fs::path& p) {
  std::map<std::string, std::vector<double>> out;
  std::ifstream f(p);
  std::string line, key;
  while (std::getline(f, line)) {
    std::istringstream s(line);
    s >> key;
    double v = 0;
    while (s >> v) out[key].push_back(v);
  }
  return out;
}

// ParaView's own scalar bar, fed from the representation's colour legend
// properties, shows the glyphs' colours over the range the renderer maps:
// MD over the data's MD range (computed independently from the input's
// tensors in pvbatch), FA over 0..1, sign over -1..1. The bar's pixels,
// found in the screenshot as the longest vertical run right of the glyphs,
// equal shaders/lib/color.glsl's map at their place on the bar within
// 1.5/255 after allowing 1.5 pixels (0.6% of the range) of placement: the
// lookup table interpolates the same knots linearly (measured: under
// 0.5/255, the 8-bit rounding). ParaView's default map fails by far; a
// range off by 2% of its span fails by 3/255 or more at every sample.
class ParaViewLegend : public ParaViewPlugin, public ::testing::WithParamInterface<int> {};

TEST_P(ParaViewLegend, ScalarBarShowsTheGlyphColoursAndRange) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const int mode = GetParam();
  const bool sign = mode == 5;
  const ShaderColormaps maps = readShaderColormaps();
  ASSERT_EQ(maps.viridis.size(), 9u) << "viridis's knots not found in color.glsl";
  ASSERT_GT(maps.tension[0], 0.5) << "signRamp's ends not found in color.glsl";
  const fs::path png = dir / "bar.png", legendFile = dir / "legend.txt";
  const CmdResult r = runPvbatch("--output " + png.string() + " " + kCamera + " --color " + std::to_string(mode) +
                                     " --scalar-bar --legend-out " + legendFile.string(),
                                 dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto legend = readLegend(legendFile);
  ASSERT_EQ(legend.count("range"), 1u);
  ASSERT_EQ(legend.at("range").size(), 2u);
  ASSERT_EQ(legend.at("lut_range"), legend.at("range")) << "the lookup table spans the legend's range";
  const double lo = legend.at("range")[0], hi = legend.at("range")[1];
  if (mode == 2) {
    const auto& md = legend.at("md_range_of_input");
    ASSERT_EQ(md.size(), 2u);
    ASSERT_LT(md[0], md[1]);
    EXPECT_NEAR(lo, md[0], 1e-6 * (md[1] - md[0]));
    EXPECT_NEAR(hi, md[1], 1e-6 * (md[1] - md[0]));
  } else {
    EXPECT_EQ(lo, sign ? -1.0 : 0.0);
    EXPECT_EQ(hi, 1.0);
  }

  const Image img = readImage(png);
  ASSERT_EQ(img.width, 400);
  // The bar: the longest run of non-background pixels in a column of the
  // right quarter (rows top to bottom); its middle column.
  int bestLen = 0, bestX = -1, bestTop = 0, lastX = -1;
  for (int x = img.width * 3 / 4; x < img.width; ++x) {
    int run = 0;
    for (int y = 0; y < img.height; ++y) {
      run = covered(img, y * img.width + x, kBackground) ? run + 1 : 0;
      if (run > bestLen) {
        bestLen = run;
        bestX = lastX = x;
        bestTop = y - run + 1;
      } else if (run == bestLen && x != lastX && bestTop == y - run + 1) {
        lastX = x;
      }
    }
  }
  ASSERT_GT(bestLen, img.height / 2) << "no scalar bar found";
  const int x = (bestX + lastX) / 2, top = bestTop, bottom = bestTop + bestLen - 1;
  for (double f = 0.05; f < 1.0; f += 0.1) {
    const int y = bottom - int(f * bestLen);
    const float* px = img.at(y * img.width + x);
    double best = 1e9;
    for (double dy = -1.5; dy <= 1.5; dy += 0.25) {
      const double frac = (double(bottom - y) + 0.5 + dy) / double(bottom - top + 1);
      const auto want = shaderColor(maps, sign, sign ? 2.0 * frac - 1.0 : frac);
      double err = 0;
      for (int k = 0; k < 3; ++k) err = std::max(err, std::abs(double(px[k]) - want[k]));
      best = std::min(best, err);
    }
    EXPECT_LE(best, 1.5 / 255.0) << "error " << best * 255.0 << "/255 at " << f << " of its length (row " << y << ", column " << x << ")";
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, ParaViewLegend, ::testing::Values(1, 2, 5));

// A dataset without tensors (a scalar map, or the 7-component masked tensors
// ParaView's NRRD reader gives as plain scalars) drew a blank view and said
// nothing; the representation now warns in ParaView's output messages.
TEST_F(ParaViewPlugin, DatasetWithoutTensorsIsSaidSo) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path in = dir / "scalars.vtk", png = dir / "scalars.png";
  std::ofstream(in) << "# vtk DataFile Version 3.0\nscalars only\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
                       "0 0 0 1 0 0 0 1 0\nPOINT_DATA 3\nSCALARS fa float 1\nLOOKUP_TABLE default\n0.1 0.5 0.9\n";
  const CmdResult r = runPvbatch("--output " + png.string() + " --input " + in.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("but no point array of tensors"), std::string::npos) << r.err;
  const CmdResult kitten = runPvbatch("--output " + png.string() + " " + kCamera, dir);
  ASSERT_EQ(kitten.code, 0) << kitten.err;
  EXPECT_EQ(kitten.err.find("but no point array of tensors"), std::string::npos) << kitten.err;
}

}  // namespace
