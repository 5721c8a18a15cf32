// The plugin's properties against the command line's options: the same
// ranges refused in the same words, the same sizing choices drawing the same
// picture, and the input domain that keeps the representation to tensors.
#include <gtest/gtest.h>

#include <filesystem>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "paraview/paraview_run.h"

namespace {

using namespace tg::test::pv;

long glyphPixelsOf(const Image& img) {
  long n = 0;
  for (int i = 0; i < img.width * img.height; ++i) n += covered(img, i, kBackground);
  return n;
}

// What follows "must be within " in `err` after `name`, to the end of its
// line or the "; kept" the plugin adds: the range as the CLI words it.
std::string rangeSaid(const std::string& err, const std::string& name) {
  const std::string key = name + " must be within ";
  const std::size_t at = err.find(key);
  if (at == std::string::npos) return "";
  const std::size_t from = at + key.size();
  std::size_t to = err.find_first_of(";\n", from);
  if (to == std::string::npos) to = err.size();
  // The plugin's messages come through ParaView's coloured log lines.
  std::string s = err.substr(from, to - from);
  if (const std::size_t esc = s.find('\x1b'); esc != std::string::npos) s.resize(esc);
  return s;
}

struct Refusal {
  std::string property, value, flag;
};

// Each property set beyond the CLI's range is refused with the CLI's range in
// the CLI's words ("NAME must be within RANGE"), and the value held is kept:
// the picture is the default one, not blank (a scale factor of 0 or -1 drew
// nothing, and Gamma 20000 was taken past its domain).
TEST_F(ParaViewPlugin, OutOfRangeValuesAreRefusedInTheCliWords) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const std::vector<Refusal> refusals = {
      {"TensorGlyphGamma", "20000", "--gamma"},
      {"TensorGlyphScaleFactor", "0", "--scale"},
      {"TensorGlyphScaleFactor", "-1", "--scale"},
      {"TensorGlyphFAThreshold", "2", "--fa-min"},
      {"TensorGlyphMarchIterations", "0", "--iterations"},
      {"TensorGlyphMarchEpsilon", "1", "--epsilon"},
      {"TensorGlyphClamp", "0.001", "--clamp"},
  };
  const fs::path plain = dir / "plain.png", bad = dir / "bad.png", cliOut = dir / "cli.png";
  // The clamp is read with its default off; 2 spacings is the default's.
  std::string sets = " --set TensorGlyphClampDefault 0 --set TensorGlyphClamp 2";
  for (const Refusal& r : refusals) sets += " --set " + r.property + " " + r.value;
  const CmdResult a = runPvbatch("--output " + plain.string() + " " + kCamera, dir);
  ASSERT_EQ(a.code, 0) << a.err;
  const CmdResult b = runPvbatch("--output " + bad.string() + " " + kCamera + sets, dir);
  ASSERT_EQ(b.code, 0) << b.err;
  for (const Refusal& r : refusals) {
    const CmdResult c = tg::test::runBinary("render " + kKitten + " " + r.flag + "=" + r.value + " -o " +
                                                cliOut.string(), dir);
    EXPECT_EQ(c.code, 2) << r.flag << " " << r.value << ": " << c.err;
    const std::string cli = rangeSaid(c.err, r.flag);
    ASSERT_FALSE(cli.empty()) << r.flag << ": " << c.err;
    EXPECT_EQ(rangeSaid(b.err, r.property), cli) << r.property << " " << r.value << ": " << b.err;
  }
  EXPECT_NE(b.err.find("SetScaleFactor: TensorGlyphScaleFactor must be within"), std::string::npos) << b.err;
  const Image x = readImage(plain), y = readImage(bad);
  ASSERT_EQ(x.width, 400);
  ASSERT_EQ(y.width, x.width);
  ASSERT_GT(glyphPixelsOf(x), 2000);
  EXPECT_EQ(differing(x, y, 0.0f), 0) << "a refused value must leave the picture as it was";
}

// The kinds outside the table's rows are refused too, in the same words.
TEST_F(ParaViewPlugin, GlyphKindOutsideTheTableIsRefused) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path png = dir / "kind.png";
  const CmdResult r = runPvbatch("--output " + png.string() + " " + kCamera + " --set TensorGlyphKind 4", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(rangeSaid(r.err, "TensorGlyphKind"), "0..3") << r.err;
  EXPECT_GT(glyphPixelsOf(readImage(png)), 2000);
}

// The CLI's magnitude mapping and clamp through the plugin's properties: the
// same picture as `render --magnitude log --clamp 0.5`, and another than the
// default one (the properties take effect).
TEST_F(ParaViewPlugin, MagnitudeMappingAndClampMatchTheCli) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path cli = dir / "cli.png", pv = dir / "pv.png", plain = dir / "plain.png";
  const CmdResult c =
      tg::test::runBinary("render " + kKitten + " --glyph ellipsoid --color dec --magnitude log --clamp 0.5 -o " + cli.string() + " " + kCamera, dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const CmdResult r = runPvbatch("--output " + pv.string() + " " + kCamera +
                                     " --set TensorGlyphMagnitude 1 --set TensorGlyphClampDefault 0"
                                     " --set TensorGlyphClamp 0.5",
                                 dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const CmdResult p = runPvbatch("--output " + plain.string() + " " + kCamera, dir);
  ASSERT_EQ(p.code, 0) << p.err;
  const Image a = readImage(cli), b = readImage(pv), d = readImage(plain);
  ASSERT_EQ(a.width, 400);
  ASSERT_EQ(b.width, a.width);
  ASSERT_EQ(d.width, a.width);
  ASSERT_GT(glyphPixelsOf(a), 2000);
  EXPECT_LE(differing(a, b, 1.0f / 255.0f), a.width * a.height / 1000);
  EXPECT_GT(differing(b, d, 1.0f / 255.0f), 1000) << "log mapping and clamp 0.5 must change the picture";
}

// The plugin does not choose the CLI's stress defaults for a stress field:
// its defaults are the same for every field (kPluginLook). The CLI's stress
// look is three properties away, and with them the plugin draws the CLI's
// default picture of the kitten, a stress field (superquadrics, the sign
// colour, log magnitudes; no legend below 480 rows).
TEST_F(ParaViewPlugin, StressLookPropertiesDrawTheClisStressDefaults) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path cli = dir / "cli.png", pv = dir / "pv.png";
  const CmdResult c = tg::test::runBinary("render " + kKitten + " -o " + cli.string() + " " + kCamera + " --verbose", dir);
  ASSERT_EQ(c.code, 0) << c.err;
  ASSERT_NE(c.err.find("stress defaults"), std::string::npos) << "the CLI must take the kitten for stress: " << c.err;
  const CmdResult r = runPvbatch("--output " + pv.string() + " " + kCamera +
                                     " --glyph 1 --color 5 --set TensorGlyphMagnitude 1",
                                 dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const Image a = readImage(cli), b = readImage(pv);
  ASSERT_EQ(a.width, 400);
  ASSERT_EQ(b.width, a.width);
  ASSERT_GT(glyphPixelsOf(a), 2000);
  EXPECT_LE(differing(a, b, 1.0f / 255.0f), a.width * a.height / 1000);
}

// The glyphs' input domain (point tensors of 9 or 6 components) rejects a
// dataset of scalars and accepts the kitten's stress tensors.
TEST_F(ParaViewPlugin, InputDomainKeepsTheRepresentationToTensors) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path in = dir / "scalars.vtk", png = dir / "r.png", out = dir / "repr.txt";
  std::ofstream(in) << "# vtk DataFile Version 3.0\nscalars only\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
                       "0 0 0 1 0 0 0 1 0\nPOINT_DATA 3\nSCALARS fa float 1\nLOOKUP_TABLE default\n0.1 0.5 0.9\n";
  const CmdResult s =
      runPvbatch("--output " + png.string() + " --input " + in.string() + " --representations-out " + out.string(), dir);
  ASSERT_EQ(s.code, 0) << s.err;
  const std::string scalars = tg::test::slurp(out);
  EXPECT_NE(scalars.find("in_domain 0"), std::string::npos) << scalars;
  const CmdResult k = runPvbatch("--output " + png.string() + " " + kCamera + " --representations-out " + out.string(), dir);
  ASSERT_EQ(k.code, 0) << k.err;
  const std::string kitten = tg::test::slurp(out);
  EXPECT_NE(kitten.find("in_domain 1"), std::string::npos) << kitten;
  EXPECT_NE(kitten.find("offered Tensor Glyphs (ray cast)"), std::string::npos) << kitten;
}

}  // namespace

namespace {

// The CLI's --stride through TensorGlyphStride: every third point of the
// kitten, the same picture as `render --stride 3` (absolute scale, so that
// the comparison does not rest on how either sizes a selection), and fewer
// glyph pixels than all points.
TEST_F(ParaViewPlugin, StrideMatchesTheCli) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path cli = dir / "cli.png", pv = dir / "pv.png", all = dir / "all.png";
  const std::string sizing = " --scale-mode absolute --scale 0.0178";
  const CmdResult c =
      tg::test::runBinary("render " + kKitten + kPluginLook + sizing + " --stride 3 -o " + cli.string() + " " + kCamera, dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const std::string pvSizing = " --scale-mode 0 --scale 0.0178";
  const CmdResult r = runPvbatch("--output " + pv.string() + " " + kCamera + pvSizing + " --set TensorGlyphStride 3", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const CmdResult a = runPvbatch("--output " + all.string() + " " + kCamera + pvSizing, dir);
  ASSERT_EQ(a.code, 0) << a.err;
  const Image x = readImage(cli), y = readImage(pv), z = readImage(all);
  ASSERT_EQ(x.width, 400);
  ASSERT_EQ(y.width, x.width);
  ASSERT_EQ(z.width, x.width);
  ASSERT_GT(glyphPixelsOf(x), 1000);
  EXPECT_LE(differing(x, y, 1.0f / 255.0f), x.width * x.height / 1000);
  EXPECT_LT(glyphPixelsOf(y), glyphPixelsOf(z));
}

// A point array as the mask (the kitten's "fixed", 0 or 1): a threshold
// below every value draws what no mask draws; 0.5 draws the fixed points
// only, fewer but some; above every value nothing, said in the CLI's
// checkLoaded terms with the count.
TEST_F(ParaViewPlugin, MaskArrayKeepsPointsAtOrAboveMaskMin) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path plain = dir / "plain.png", low = dir / "low.png", half = dir / "half.png", high = dir / "high.png";
  const std::string mask = " --mask-array fixed --set TensorGlyphUseMask 1 --set TensorGlyphMaskMin ";
  const CmdResult a = runPvbatch("--output " + plain.string() + " " + kCamera, dir);
  ASSERT_EQ(a.code, 0) << a.err;
  const CmdResult b = runPvbatch("--output " + low.string() + " " + kCamera + mask + "-1", dir);
  ASSERT_EQ(b.code, 0) << b.err;
  const CmdResult c = runPvbatch("--output " + half.string() + " " + kCamera + mask + "0.5", dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const CmdResult d = runPvbatch("--output " + high.string() + " " + kCamera + mask + "2", dir);
  ASSERT_EQ(d.code, 0) << d.err;
  const Image p = readImage(plain), l = readImage(low), h = readImage(half), n = readImage(high);
  ASSERT_EQ(p.width, 400);
  ASSERT_EQ(l.width, p.width);
  ASSERT_EQ(h.width, p.width);
  ASSERT_EQ(n.width, p.width);
  ASSERT_GT(glyphPixelsOf(p), 2000);
  EXPECT_EQ(differing(p, l, 0.0f), 0);
  EXPECT_GT(glyphPixelsOf(h), 0);
  EXPECT_LT(glyphPixelsOf(h), glyphPixelsOf(p));
  EXPECT_EQ(glyphPixelsOf(n), 0);
  EXPECT_NE(d.err.find("no tensor to draw: 14961 masked (TensorGlyphMaskMin 2), 0 left out by TensorGlyphStride 1"),
            std::string::npos)
      << d.err;
}

// 2-D stress as OpenGeoSys writes it (4 components XX YY ZZ XY named
// sigma), which the CLI reads and the plugin refused: the same picture.
TEST_F(ParaViewPlugin, TwoDimensionalStressMatchesTheCli) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path in = dir / "plane.vtk", cli = dir / "cli.png", pv = dir / "pv.png";
  {
    std::ofstream f(in);
    f << "# vtk DataFile Version 3.0\n2-D stress\nASCII\nDATASET POLYDATA\nPOINTS 25 float\n";
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) f << i << " " << j << " 0\n";
    f << "POINT_DATA 25\nFIELD FieldData 1\nsigma 4 25 float\n";
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) f << 1.0 + 0.2 * i << " " << 0.4 + 0.1 * j << " " << 0.3 << " " << 0.1 * (i - j) << "\n";
  }
  const std::string camera = " --size 400 300 --eye 2 2 12 --look-at 2 2 0 --up 0 1 0 --fov 30";
  const CmdResult c = tg::test::runBinary(
      "render " + in.string() + kPluginLook + " --scale-mode absolute --scale 0.6 -o " + cli.string() + camera, dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const CmdResult r = runPvbatch("--output " + pv.string() + " --input " + in.string() + camera +
                                     " --scale-mode 0 --scale 0.6 --tensors sigma",
                                 dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const Image x = readImage(cli), y = readImage(pv);
  ASSERT_EQ(x.width, 400);
  ASSERT_EQ(y.width, x.width);
  ASSERT_GT(glyphPixelsOf(x), 2000);
  EXPECT_LE(differing(x, y, 1.0f / 255.0f), x.width * x.height / 1000);
}

}  // namespace

namespace {

double meanGlyphLuminance(const Image& img) {
  double sum = 0;
  long n = 0;
  for (int i = 0; i < img.width * img.height; ++i)
    if (covered(img, i, kBackground)) {
      sum += (img.at(i)[0] + img.at(i)[1] + img.at(i)[2]) / 3.0;
      ++n;
    }
  return n ? sum / double(n) : 0.0;
}

// The view's light kit: its default key light (0.75) is the CLI's picture
// (PictureMatchesTheCli); a dimmer key light darkens the glyphs, and the kit
// off leaves only the head light and the ambient term, darker still.
TEST_F(ParaViewPlugin, LightKitKeyIntensityLightsTheGlyphs) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path plain = dir / "plain.png", dim = dir / "dim.png", off = dir / "off.png";
  const CmdResult a = runPvbatch("--output " + plain.string() + " " + kCamera, dir);
  ASSERT_EQ(a.code, 0) << a.err;
  const CmdResult b = runPvbatch("--output " + dim.string() + " " + kCamera + " --view-set KeyLightIntensity 0.25", dir);
  ASSERT_EQ(b.code, 0) << b.err;
  const CmdResult c = runPvbatch("--output " + off.string() + " " + kCamera + " --view-set UseLight 0", dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const Image x = readImage(plain), y = readImage(dim), z = readImage(off);
  ASSERT_EQ(x.width, 400);
  ASSERT_EQ(y.width, x.width);
  ASSERT_EQ(z.width, x.width);
  ASSERT_GT(glyphPixelsOf(x), 2000);
  EXPECT_EQ(glyphPixelsOf(y), glyphPixelsOf(x)) << "light changes shading, not coverage";
  const double lx = meanGlyphLuminance(x), ly = meanGlyphLuminance(y), lz = meanGlyphLuminance(z);
  EXPECT_LT(ly, lx - 0.02) << lx << " " << ly;
  EXPECT_LT(lz, ly - 0.01) << ly << " " << lz;
}

// Opacity below 1 shows what lies behind the glyphs: with a ParaView slice
// behind and in front of them, each pixel at Opacity 0.5 is the mean of the
// opaque glyphs' picture and the slice's picture without glyphs (where the
// slice is in front, both are the slice), within 8-bit rounding; and most
// glyph pixels differ from the opaque ones. The glyphs stay where they were.
TEST_F(ParaViewPlugin, OpacityShowsWhatLiesBehindTheGlyphs) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path opaque = dir / "opaque.png", slice = dir / "slice.png", half = dir / "half.png";
  const std::string plane = " --slice-normal 0 0 1 --slice-origin -1.5 41.8 5.6";
  const CmdResult a = runPvbatch("--output " + opaque.string() + " " + kCamera + plane, dir);
  ASSERT_EQ(a.code, 0) << a.err;
  const CmdResult b = runPvbatch("--output " + slice.string() + " " + kCamera + plane + " --no-glyphs", dir);
  ASSERT_EQ(b.code, 0) << b.err;
  const CmdResult c = runPvbatch("--output " + half.string() + " " + kCamera + plane + " --set Opacity 0.5", dir);
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_EQ(c.err.find("Opacity"), std::string::npos) << c.err;
  const Image x = readImage(opaque), y = readImage(slice), z = readImage(half);
  ASSERT_EQ(x.width, 400);
  ASSERT_EQ(y.width, x.width);
  ASSERT_EQ(z.width, x.width);
  long glyphs = 0, seeThrough = 0, off = 0;
  for (int i = 0; i < x.width * x.height; ++i) {
    bool glyph = false, differs = false, wrong = false;
    for (int k = 0; k < 3; ++k) {
      const float g = x.at(i)[k], behind = y.at(i)[k], got = z.at(i)[k];
      glyph |= std::abs(g - behind) > 4.0f / 255.0f;
      differs |= std::abs(got - g) > 2.0f / 255.0f;
      wrong |= std::abs(got - 0.5f * (g + behind)) > 1.5f / 255.0f;
    }
    glyphs += glyph;
    seeThrough += glyph && differs;
    off += wrong;
  }
  ASSERT_GT(glyphs, 1000) << "the glyphs must show in front of the slice and the background";
  EXPECT_GT(seeThrough, glyphs * 9 / 10) << seeThrough << " of " << glyphs;
  EXPECT_LE(off, x.width * x.height / 1000) << off << " pixels are not the mean of the two pictures";
}

// ParaView's ColorBy colours the glyphs through the display's lookup table:
// a table of shaders/lib/color.glsl's viridis knots (or a grey ramp) over
// 20..60 on a point array of heights draws the CLI's picture of that array
// with that map and window, within one 8-bit step on 0.1% of the pixels (the
// table is sampled 1024 times; the CLI maps the knots exactly). Rescaling the
// table to 30..50 draws the CLI's picture of that window, with the glyph
// records uploaded once for both frames. Without the table's window (the
// CLI's 30..50 against the plugin's 20..60) most glyph pixels differ.
class ParaViewColorBy : public ParaViewPlugin, public ::testing::WithParamInterface<bool> {};

TEST_P(ParaViewColorBy, GlyphsShowTheLookupTablesColours) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const bool gray = GetParam();
  const fs::path field = dir / "height.vtu";
  const CmdResult w = runPvbatch("--input " + pvKitten() + " --write-height " + field.string(), dir);
  ASSERT_EQ(w.code, 0) << w.err;
  const ShaderColormaps maps = readShaderColormaps();
  ASSERT_EQ(maps.viridis.size(), 9u) << "viridis's knots not found in color.glsl";
  std::string points;
  const double lo = 20, hi = 60;
  if (gray) {
    points = "20 0 0 0 60 1 1 1";
  } else {
    for (std::size_t k = 0; k < maps.viridis.size(); ++k) {
      points += " " + std::to_string(lo + (hi - lo) * double(k) / double(maps.viridis.size() - 1));
      for (double c : maps.viridis[k]) points += " " + std::to_string(c);
    }
  }
  const fs::path pv = dir / "pv.png", pv2 = dir / "pv2.png", cli = dir / "cli.png", cli2 = dir / "cli2.png",
                 uploads = dir / "uploads.txt";
  const CmdResult r = runPvbatch("--input " + field.string() + " --output " + pv.string() + " " + kCamera +
                                     " --color-by height --lut-points " + points + " --lut-range 20 60 --rescale 30 50"
                                     " --rescaled-output " + pv2.string() + " --uploads-out " + uploads.string(),
                                 dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("ColorBy"), std::string::npos) << r.err;
  // The plugin's look (kPluginLook) with the array's colour instead of DEC.
  const std::string look = std::string(" --glyph ellipsoid --magnitude linear --color-array height --colormap ") +
                           (gray ? "gray" : "viridis");
  const CmdResult c = tg::test::runBinary("render " + field.string() + look + " --color-range 20 60 -o " +
                                          cli.string() + " " + kCamera, dir);
  ASSERT_EQ(c.code, 0) << c.err;
  const CmdResult c2 = tg::test::runBinary("render " + field.string() + look + " --color-range 30 50 -o " +
                                           cli2.string() + " " + kCamera, dir);
  ASSERT_EQ(c2.code, 0) << c2.err;
  const Image a = readImage(pv), a2 = readImage(pv2), b = readImage(cli), b2 = readImage(cli2);
  ASSERT_EQ(a.width, 400);
  ASSERT_EQ(a2.width, 400);
  ASSERT_EQ(b.width, 400);
  ASSERT_EQ(b2.width, 400);
  const long glyphPixels = glyphPixelsOf(b);
  ASSERT_GT(glyphPixels, 2000);
  EXPECT_LE(differing(a, b, 1.0f / 255.0f), a.width * a.height / 1000);
  EXPECT_LE(differing(a2, b2, 1.0f / 255.0f), a.width * a.height / 1000);
  EXPECT_GT(differing(a, b2, 3.0f / 255.0f), glyphPixels / 4) << "the window must change the glyphs' colours";
  std::ifstream in(uploads);
  std::string line, all;
  while (std::getline(in, line)) all += line + "\n";
  EXPECT_EQ(all, "uploads 0 1\nuploads 1 1\n") << "a new colour window must upload no glyph records";
}

INSTANTIATE_TEST_SUITE_P(Maps, ParaViewColorBy, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& p) { return p.param ? "Gray" : "Viridis"; });

// Solid Color (ColorBy None) leaves the glyphs TensorGlyphColorMode's
// colours, and an array that is no point array is said not to colour them,
// once, rather than a scalar bar over glyphs coloured otherwise.
TEST_F(ParaViewPlugin, ColorByACellArrayIsSaidNotToColourTheGlyphs) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path png = dir / "c.png";
  const std::string said = "ColorBy: 'fixed' is not a point array";
  const CmdResult r = runPvbatch("--output " + png.string() + " " + kCamera + " --color-by-cells fixed", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::size_t at = r.err.find(said);
  EXPECT_NE(at, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(said, at + 1), std::string::npos) << "said more than once: " << r.err;
  const CmdResult plain = runPvbatch("--output " + png.string() + " " + kCamera + " --color-by NONE", dir);
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_EQ(plain.err.find("ColorBy:"), std::string::npos) << plain.err;
}

}  // namespace

namespace {

std::string glyphPathSaid(const fs::path& file) {
  std::ifstream in(file);
  std::string word, path;
  in >> word >> path;
  return word == "glyph_path" ? path : "";
}

}  // namespace

// The Glyph Path property (the CLI's --pipeline): the cpu and compute paths
// draw the raster path's picture in ParaView's context too, for superquadrics and
// Teem's boxes; Auto calibrates once into the cache and then takes what
// the cache's table predicts faster.
TEST_F(ParaViewPlugin, GlyphPathsDrawTheSamePictureAndAutoFollowsItsTable) {
  TG_SKIP_WITHOUT_PARAVIEW();
  const fs::path cache = dir / "cache", said = dir / "path.txt";
  fs::remove_all(cache);
  ::setenv("TG_CACHE_DIR", cache.c_str(), 1);
  for (const char* glyph : {"1", "3"}) {
    SCOPED_TRACE(std::string("glyph kind ") + glyph);
    const fs::path raster = dir / "raster.png", other = dir / "other.png";
    const std::string base = kCamera + std::string(" --glyph ") + glyph + " --glyph-path-out " + said.string();
    const CmdResult a = runPvbatch("--output " + raster.string() + " " + base, dir);
    ASSERT_EQ(a.code, 0) << a.err;
    EXPECT_EQ(glyphPathSaid(said), "raster");
    const Image x = readImage(raster);
    ASSERT_GT(glyphPixelsOf(x), 1000);
    for (const auto& [index, path] : {std::pair{"1", "cpu"}, std::pair{"2", "compute"}}) {
      const CmdResult b = runPvbatch("--output " + other.string() + " " + base + " --set TensorGlyphPipeline " + index, dir);
      ASSERT_EQ(b.code, 0) << b.err;
      EXPECT_EQ(glyphPathSaid(said), path);
      EXPECT_LE(differing(x, readImage(other), 1.0f / 255.0f), x.width * x.height / 1000) << path;
    }
  }
  const std::string autoRun = "--output " + (dir / "auto.png").string() + " " + kCamera +
                              " --set TensorGlyphPipeline 3 --glyph-path-out " + said.string();
  const CmdResult first = runPvbatch(autoRun, dir);
  ASSERT_EQ(first.code, 0) << first.err;
  std::ifstream in(cache / "pipelines.tsv");
  std::string header, columns, row;
  std::getline(in, header);
  std::getline(in, columns);
  std::getline(in, row);
  const std::string key = row.substr(0, row.find('\t'));
  ASSERT_FALSE(key.empty()) << "no calibration kept";
  for (const auto& [rasterUs, cpuUs, computeUs, want] :
       {std::tuple{10.0, 1.0, 20.0, "cpu"}, std::tuple{1.0, 10.0, 20.0, "raster"}, std::tuple{10.0, 20.0, 1.0, "compute"}}) {
    {
      std::ofstream f(cache / "pipelines.tsv", std::ios::trunc);
      f << header << "\n" << columns << "\n";
      for (const char* cls : {"closed-form", "march"})
        f << key << "\traster\t" << cls << "\t1\t" << rasterUs << "\t10\n"
          << key << "\tcpu\t" << cls << "\t1\t" << cpuUs << "\t10\n"
          << key << "\tcompute\t" << cls << "\t1\t" << computeUs << "\t10\n";
    }
    const CmdResult r = runPvbatch(autoRun, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(glyphPathSaid(said), want);
  }
  ::unsetenv("TG_CACHE_DIR");
}
