// Tier 2: colour options through the real binary: a VTK point array by name
// (--color-array), the window (--color-range) and the map (--colormap), and
// their refusals.
#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

fs::path dir() { return tg::test::cliDir("color"); }

// A 6 x 6 x 2 point set of stress tensors, diag(a, b, c) turned about z,
// with two point scalars: "vm", each tensor's von Mises stress, and "wave".
fs::path stressWithScalars() {
  const fs::path p = dir() / "stress_scalars.vtk";
  std::ofstream f(p);
  const int n = 72;
  f << "# vtk DataFile Version 3.0\nstress with scalars\nASCII\nDATASET POLYDATA\nPOINTS " << n << " float\n";
  for (int i = 0; i < n; ++i) f << i % 6 << " " << i / 6 % 6 << " " << i / 36 << "\n";
  f << "POINT_DATA " << n << "\nTENSORS stress float\n";
  std::vector<double> vm(n);
  for (int i = 0; i < n; ++i) {
    const double a = 10.0 + i, b = -5.0 + 0.5 * i, c = -20.0 + 0.25 * i, t = 0.1 * i;
    const double cs = std::cos(t), sn = std::sin(t);
    const double xx = a * cs * cs + b * sn * sn, yy = a * sn * sn + b * cs * cs, xy = (a - b) * cs * sn;
    f << xx << " " << xy << " 0\n" << xy << " " << yy << " 0\n0 0 " << c << "\n";
    vm[i] = std::sqrt(0.5 * ((a - b) * (a - b) + (b - c) * (b - c) + (c - a) * (c - a)));
  }
  f << "SCALARS vm float 1\nLOOKUP_TABLE default\n";
  for (double v : vm) f << v << "\n";
  f << "SCALARS wave float 1\nLOOKUP_TABLE default\n";
  for (int i = 0; i < n; ++i) f << std::sin(0.3 * i) << "\n";
  return p;
}

std::vector<unsigned char> rgba(const fs::path& png, int w, int h) {
  auto in = OIIO::ImageInput::open(png.string());
  if (!in) return {};
  std::vector<unsigned char> px(std::size_t(w) * h * 4);
  in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data());
  return px;
}

const std::string kView = " --size 200 150 --ortho 9 --eye 2.5 2.5 20 --look-at 2.5 2.5 0.5 --scale-mode absolute --scale 0.02";

}  // namespace

// The array "vm" holds each tensor's von Mises stress: colouring by it draws
// the picture --color vonmises draws, pixel for pixel within a level (the
// shader computes von Mises in float, the file holds it to 6 digits), over
// the same window (its range over the field).
TEST(ColorCli, ArrayByNameDrawsWhatTheDerivedScalarDraws) {
  const fs::path in = stressWithScalars();
  const fs::path a = dir() / "by_array.png", b = dir() / "by_mode.png";
  auto r = tg::test::runBinary("render " + in.string() + kView + " --color-array vm -o " + a.string(), dir());
  ASSERT_EQ(r.code, 0) << r.err;
  r = tg::test::runBinary("render " + in.string() + kView + " --color vonmises -o " + b.string(), dir());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto pa = rgba(a, 200, 150), pb = rgba(b, 200, 150);
  ASSERT_EQ(pa.size(), pb.size());
  std::size_t glyphPixels = 0, off = 0;
  for (std::size_t i = 0; i < pa.size(); i += 4) {
    glyphPixels += pa[i] != pa[0] || pa[i + 1] != pa[1] || pa[i + 2] != pa[2];
    for (int k = 0; k < 3; ++k) off += std::abs(int(pa[i + k]) - int(pb[i + k])) > 1;
  }
  EXPECT_GT(glyphPixels, 500u);
  EXPECT_EQ(off, 0u);
  // Another array draws another picture.
  const fs::path c = dir() / "wave.png";
  r = tg::test::runBinary("render " + in.string() + kView + " --color-array wave -o " + c.string(), dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(rgba(c, 200, 150), pa);
}

// An unknown array: exit 2, one line naming the option, the file and the
// arrays it has; no output.
TEST(ColorCli, UnknownArrayNamesTheArraysAvailable) {
  const fs::path in = stressWithScalars(), out = dir() / "none.png";
  fs::remove(out);
  const auto r = tg::test::runBinary("render " + in.string() + " --color-array temperature -o " + out.string(), dir());
  EXPECT_EQ(r.code, 2) << r.err;
  for (const char* word : {"--color-array", "temperature", "vm (1 components)", "wave (1 components)"})
    EXPECT_NE(r.err.find(word), std::string::npos) << word << " in " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// Bad colour options are command-line errors (exit 2), each naming its option.
TEST(ColorCli, BadColourOptionsAreRefused) {
  const fs::path in = stressWithScalars(), out = dir() / "bad.png";
  const struct {
    std::string flags, what;
  } cases[] = {
      {"--color vonmises --color-range nan 1", "--color-range: \"nan\" is not a finite number"},
      {"--color vonmises --color-range 0 1e300", "--color-range must be within"},
      {"--color vonmises --color-range 5 5", "--color-range: LO 5 must be below HI 5"},
      {"--color vonmises --color-range 6 2", "--color-range: LO 6 must be below HI 2"},
      {"--color dec --color-range 0 1", "--color-range: --color dec maps directions"},
      {"--color md --colormap jet", "--colormap: unknown map \"jet\""},
      {"--color sign --colormap gray", "--colormap: --color sign has colours of its own"},
      {"--color array", "--color array needs --color-array NAME"},
      {"--color vm", "--color: unknown mode \"vm\""},
  };
  for (const auto& c : cases) {
    fs::remove(out);
    const auto r = tg::test::runBinary("render " + in.string() + " " + c.flags + " -o " + out.string(), dir());
    EXPECT_EQ(r.code, 2) << c.flags << ": " << r.err;
    EXPECT_NE(r.err.find(c.what), std::string::npos) << c.flags << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.flags;
  }
}

// --color-range fixes the window: the picture changes with it (the legend's
// ends: ColorBy.AFixedWindowShowsOnTheLegend).
TEST(ColorCli, ColorRangeChangesThePicture) {
  const fs::path in = stressWithScalars();
  const fs::path a = dir() / "auto.png", b = dir() / "fixed.png";
  auto r = tg::test::runBinary("render " + in.string() + kView + " --color vonmises -o " + a.string(), dir());
  ASSERT_EQ(r.code, 0) << r.err;
  r = tg::test::runBinary("render " + in.string() + kView + " --color vonmises --color-range 20 40 -o " + b.string(),
                          dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(rgba(a, 200, 150), rgba(b, 200, 150));
}
