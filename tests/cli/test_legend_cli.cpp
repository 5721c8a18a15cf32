// Tier 2: `render --legend` and its flags through the real binary.
#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

fs::path dir() { return tg::test::cliDir("legend"); }

std::vector<unsigned char> renderRgba(const std::string& flags, const std::string& name) {
  const fs::path out = dir() / name;
  const auto r = tg::test::runBinary("render -o " + out.string() + " --size 320 240 " + flags, dir());
  EXPECT_EQ(r.code, 0) << r.err;
  auto in = OIIO::ImageInput::open(out.string());
  if (!in) return {};
  std::vector<unsigned char> px(320 * 240 * 4);
  in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data());
  return px;
}

// The bounding box of the pixels that differ between two frames.
struct Box {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
Box differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
  Box box;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 320; ++x) {
      const std::size_t i = 4 * (std::size_t(y) * 320 + x);
      if (a[i] == b[i] && a[i + 1] == b[i + 1] && a[i + 2] == b[i + 2]) continue;
      box = {std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x), std::max(box.y1, y)};
    }
  return box;
}

}  // namespace

// --legend changes one corner of the frame, the one --legend-corner names.
// The camera is given (--ortho): a chosen one would move to leave the legend room.
TEST(LegendCli, LegendDrawsInTheCornerAsked) {
  const auto plain = renderRgba("--color fa --ortho 50 --no-legend", "plain.png");
  const auto br = renderRgba("--color fa --ortho 50 --legend", "br.png");
  const auto tl = renderRgba("--color fa --ortho 50 --legend --legend-corner top-left --units MPa", "tl.png");
  ASSERT_FALSE(plain.empty() || br.empty() || tl.empty());
  const Box a = differing(plain, br), b = differing(plain, tl);
  ASSERT_GE(a.x1, 0);
  ASSERT_GE(b.x1, 0);
  EXPECT_GT(a.x0, 40);  // bottom right, clear of the opposite corner
  EXPECT_GT(a.y0, 60);
  EXPECT_GE(a.x1, 300);
  EXPECT_GE(a.y1, 220);
  EXPECT_LE(b.x0, 20);  // top left
  EXPECT_LE(b.y0, 20);
  EXPECT_LT(b.x1, 280);
  EXPECT_LT(b.y1, 180);
}

TEST(LegendCli, BadLegendFlagsAreUsageErrors) {
  const fs::path out = dir() / "bad.png";
  const std::pair<std::string, std::string> cases[] = {
      {"--units MPa", "need --legend"},
      {"--legend --legend-corner middle", "--legend-corner: unknown corner \"middle\""},
      {"--legend --legend-text-scale 9", "--legend-text-scale"},
      {"--legend --units " + std::string(41, 'u'), "--units: at most 40 characters"}};
  for (const auto& [flags, what] : cases) {
    tg::test::expectFailsCleanly("render -o " + out.string() + " " + flags, what, out, dir(), 1);
    const auto r = tg::test::runBinary("render -o " + out.string() + " " + flags, dir());
    EXPECT_EQ(r.code, 2) << flags;
  }
}

// On a transparent background the legend is in the alpha channel too (it
// once kept the target's alpha, 0 there, and vanished from the image), and a
// legend the image cannot hold is said to be cut off.
TEST(LegendCli, LegendIsOpaqueOnATransparentBackgroundAndSaysWhenCutOff) {
  const auto px = renderRgba("--color fa --no-shadows --no-ao --background 0 0 0 0 --legend", "alpha.png");
  ASSERT_FALSE(px.empty());
  const auto alpha = [&](int x, int y) { return int(px[4 * (std::size_t(y) * 320 + x) + 3]); };
  EXPECT_EQ(alpha(2, 2), 0);        // the background, far from glyphs and legend
  EXPECT_GT(alpha(300, 225), 150);  // inside the legend's panel (bottom right, 8 px in)
  const fs::path out = dir() / "tiny.png";
  const auto r = tg::test::runBinary("render -o " + out.string() + " --size 120 90 --legend", dir());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("--legend: the legend needs"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is cut off by the 120 x 90 image"), std::string::npos) << r.err;
}
