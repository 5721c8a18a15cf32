#pragma once
// Small golden images, as Magnum keeps them: a frame against
// tests/golden/NAME.png by the largest and the mean per-channel difference in
// 8-bit levels, each threshold justified where it is used. TG_UPDATE_GOLDEN=1
// rewrites the image (look at it before committing); a mismatch leaves the
// frame as NAME-actual.png in the temporary directory.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "io/core/image_writer.h"
#include "view/frame_image.h"

namespace tg::test {

inline void expectMatchesGolden(const render::FrameImage& img, const std::string& name, int maxLevels,
                                double meanLevels) {
  const std::string golden = std::string(TG_SOURCE_DIR) + "/tests/golden/" + name + ".png";
  if (const char* u = std::getenv("TG_UPDATE_GOLDEN"); u && std::string(u) == "1") io::writeImage(img, golden);
  auto in = OIIO::ImageInput::open(golden);
  ASSERT_TRUE(in) << golden;
  ASSERT_EQ(in->spec().width, img.width) << golden;
  ASSERT_EQ(in->spec().height, img.height) << golden;
  std::vector<unsigned char> want(std::size_t(img.width) * img.height * 4);
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, want.data())) << golden;
  ASSERT_EQ(img.rgba.size(), want.size());
  int worst = 0;
  double sum = 0;
  for (std::size_t k = 0; k < want.size(); ++k) {
    // As io::writeImage quantises PNG output.
    const int have = int(std::clamp(img.rgba[k], 0.0f, 1.0f) * 255.0f + 0.5f);
    const int diff = std::abs(have - int(want[k]));
    worst = std::max(worst, diff);
    sum += diff;
  }
  const double mean = sum / double(want.size());
  if (worst > maxLevels || mean > meanLevels) {
    const auto actual = std::filesystem::temp_directory_path() / (name + "-actual.png");
    io::writeImage(img, actual.string());
    ADD_FAILURE() << name << ": max " << worst << " (limit " << maxLevels << "), mean " << mean << " (limit "
                  << meanLevels << "); actual image: " << actual;
  }
}

}  // namespace tg::test
