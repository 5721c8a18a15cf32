// Tier 3: the 8-bit colour readback (render/color_readback.h) reads the lit
// colour in bands of rows and never holds the float image; it must give the
// bytes io::toRgba8 makes of the float readback, and so the same files.
#include "render_fixture.h"

#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

#include "io/core/image_writer.h"
#include "render/color_readback.h"

using namespace tg;
using test::GlFixture;

namespace {

std::string fileBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class ColorReadback : public GlFixture {};

}  // namespace

TEST(ColorBands, AtLeastOneRowAndWithin256KiB) {
  EXPECT_EQ(render::colorBandRows(512), 32);
  EXPECT_EQ(render::colorBandRows(300), 54);
  EXPECT_EQ(render::colorBandRows(1 << 20), 1);
  EXPECT_EQ(render::colorBandRows(1), 16384);
}

// 300 x 170: four bands of 54 rows, the last of 8, so a band boundary or a
// row flipped into the wrong band shows.
TEST_F(ColorReadback, Rgba8IsTheFloatImageRoundedBandByBand) {
  ctx_->makeCurrent();
  const auto set = test::glyphsOf(test::mixedGrid(8, 17));
  const double scale = 0.4 / set.maxAbsEigenvalue;
  for (const render::GlyphKind kind : {render::GlyphKind::Ellipsoid, render::GlyphKind::Superquadric}) {
    SCOPED_TRACE(int(kind));
    const auto cam = test::cameraFor(set, scale, test::oblique(set, 18.0, render::Projection::Perspective), 300, 170);
    ASSERT_LT(render::colorBandRows(cam.width), cam.height);
    ASSERT_NE(cam.height % render::colorBandRows(cam.width), 0);
    render::FrameParams p;
    p.glyph = kind;
    p.scale = scale;
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    r.render(cam, p, target);
    const render::FrameImage full = r.readback(cam, target, render::Channels::All);
    const render::FrameImage bytes = r.readback(cam, target, render::Channels::Rgba8);
    EXPECT_TRUE(bytes.rgba.empty());
    EXPECT_TRUE(bytes.id.empty());
    EXPECT_EQ(bytes.width, cam.width);
    EXPECT_EQ(bytes.height, cam.height);
    const std::vector<unsigned char> expected = io::toRgba8(full);
    ASSERT_EQ(bytes.rgba8.size(), expected.size());
    EXPECT_TRUE(bytes.rgba8 == expected);
    // Not a blank frame: glyphs and background both.
    std::size_t covered = 0;
    for (const std::uint32_t id : full.id) covered += id != 0xFFFFFFFFu;
    EXPECT_GT(covered, 1000u);
    EXPECT_LT(covered, full.id.size() / 2);

    // The same PNG from either frame; EXR needs the float channels.
    const auto dir = std::filesystem::temp_directory_path() / ("tg_readback_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    io::writeImage(full, (dir / "float.png").string());
    io::writeImage(bytes, (dir / "bytes.png").string());
    EXPECT_EQ(fileBytes(dir / "float.png"), fileBytes(dir / "bytes.png"));
    EXPECT_THROW(io::writeImage(bytes, (dir / "bytes.exr").string()), std::runtime_error);
    std::filesystem::remove_all(dir);
  }
}
