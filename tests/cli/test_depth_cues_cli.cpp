// The depth cues through the binary: golden images per effect, and the
// flags' contract (ranges, a parameter without its switch).
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli_run.h"

namespace fs = std::filesystem;
using tg::test::CmdResult;

namespace {

fs::path dir() { return tg::test::cliDir("cli_cues"); }

CmdResult run(const std::string& args) { return tg::test::runBinary(args, dir()); }

std::vector<unsigned char> rgba8(const fs::path& p, int w, int h) {
  std::vector<unsigned char> px(std::size_t(w * h * 4));
  auto in = OIIO::ImageInput::open(p.string());
  EXPECT_TRUE(in) << p;
  if (!in) return {};
  EXPECT_EQ(in->spec().width, w);
  EXPECT_EQ(in->spec().height, h);
  EXPECT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data()));
  return px;
}

struct Diff {
  int max = 0;
  double mean = 0;
};

Diff diff(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
  Diff d;
  if (a.size() != b.size() || a.empty()) return {255, 255};
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int e = std::abs(int(a[i]) - int(b[i]));
    d.max = std::max(d.max, e);
    d.mean += e;
  }
  d.mean /= double(a.size());
  return d;
}

// The synthetic helix (500 glyphs: isotropic spheres round a helix of
// linear ones), superquadrics, close up: dense enough that glyphs touch.
const char* kView = " --size 128 96 --glyph superquadric --eye 2 -9 9 --look-at 2 0 0 --scale-mode spacing --scale 1.3";

fs::path helix() {
  const fs::path f = dir() / "helix10.vtk";
  if (!fs::exists(f)) {
    EXPECT_EQ(run("synth helix --n 10 -o " + f.string()).code, 0);
  }
  return f;
}

// Renders with `flags` and checks the golden image; returns how far the
// same view without the effect lies from that golden (what a lost effect
// would score).
Diff expectGolden(const std::string& flags, const std::string& golden) {
  const fs::path on = dir() / "on.png", off = dir() / "off.png";
  const CmdResult r = run("render " + helix().string() + kView + " " + flags + " -o " + on.string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(run("render " + helix().string() + kView + " -o " + off.string()).code, 0);
  const auto ref = rgba8(fs::path(TG_SOURCE_DIR) / "tests/golden" / golden, 128, 96);
  const Diff d = diff(rgba8(on, 128, 96), ref);
  // Max 40/255, as the default scene's golden: another llvmpipe build may
  // shade a few levels differently, but a line or a shadow gained or lost
  // moves a pixel by 60 to 255 levels. Mean 0.6/255: below one level of
  // drift on average; the effect itself moves the mean by 10.0 (AO) and 27.8
  // (outlines) levels, checked below.
  EXPECT_LE(d.max, 40) << golden;
  EXPECT_LE(d.mean, 0.6) << golden;
  return diff(rgba8(off, 128, 96), ref);
}

}  // namespace

// Regenerate with: tensorglyph synth helix --n 10 -o h.vtk; tensorglyph
// render h.vtk <kView> --ao -o tests/golden/ao-helix.png (--outlines for
// outlines-helix.png); and look at them.
TEST(DepthCuesCli, AmbientOcclusionMatchesGoldenImage) {
  const Diff off = expectGolden("--ao", "ao-helix.png");
  EXPECT_GT(off.mean, 5.0) << "the golden shows the occlusion";  // half of 10.0
}

TEST(DepthCuesCli, OutlinesMatchGoldenImage) {
  const Diff off = expectGolden("--outlines", "outlines-helix.png");
  EXPECT_GT(off.mean, 14.0) << "the golden shows the lines";  // half of 27.8
  EXPECT_EQ(off.max, 255);
}

// Anti-aliasing: the one-sample and the 4-sample pictures each match their
// golden (render <kView> [--samples 4] -o tests/golden/samplesN-helix.png),
// and differ from each other only where it shows: measured mean 1.14/255
// over the image, 717 of 12,288 pixels, at most 118 levels.
TEST(DepthCuesCli, AntiAliasingMatchesGoldenImagesAtOneAndFourSamples) {
  const Diff plain = expectGolden("", "samples1-helix.png");
  EXPECT_LE(plain.max, 40);  // as every golden (expectGolden); the GL test holds it bit for bit
  const Diff off = expectGolden("--samples 4", "samples4-helix.png");
  EXPECT_GT(off.mean, 0.57) << "the golden shows the smoothed silhouettes";  // half of 1.14
  EXPECT_GT(off.max, 70);
}

TEST(DepthCuesCli, BadEffectFlagsFailCleanly) {
  const fs::path out = dir() / "bad.png";
  const std::pair<std::string, std::string> cases[] = {
      {"--ao-radius 0.1", "need --ao"},
      {"--outline-width 2", "need --outlines"},
      {"--ao --ao-radius 0", "--ao-radius must be within"},
      {"--ao --ao-radius nan", "--ao-radius"},
      {"--ao --ao-strength 5", "--ao-strength must be within 0..4"},
      {"--ao --ao-samples 1000", "--ao-samples"},
      {"--outlines --outline-width 9", "--outline-width must be within 0.25..8"},
      {"--outlines --outline-color 1 0 0", "--outline-color"},
      {"--outlines --outline-crease 180", "--outline-crease"},
      {"--samples 0", "--samples must be within 1..16"},
      {"--samples 17", "--samples must be within 1..16"}};
  for (const auto& [flags, what] : cases) {
    tg::test::expectFailsCleanly("render -o " + out.string() + " --size 32 24 " + flags, what, out, dir(), 2);
    EXPECT_EQ(run("render -o " + out.string() + " --size 32 24 " + flags).code, 2) << flags;
  }
}
