#include "render/color_readback.h"

#include <algorithm>
#include <memory>

#include "render/frame_image.h"

namespace tg::render {

int colorBandRows(int width) {
  constexpr std::size_t kColorBandBytes = std::size_t(256) << 10;
  const std::size_t row = std::size_t(std::max(width, 1)) * 4 * sizeof(float);
  return int(std::max<std::size_t>(1, kColorBandBytes / row));
}

std::vector<std::uint8_t> readColorRgba8(const gl::Api& gl, const GBuffer& target) {
  const int w = target.width(), h = target.height();
  const std::size_t row = std::size_t(w) * 4;
  std::vector<std::uint8_t> out(row * std::size_t(h));
  const int band = colorBandRows(w);
  // Uninitialised: GL writes every float before it is read.
  const std::unique_ptr<float[]> floats(new float[row * std::size_t(std::min(band, h))]);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  for (int y0 = 0; y0 < h; y0 += band) {
    const int rows = std::min(band, h - y0);
    gl.GetTextureSubImage(target.color(), 0, 0, y0, 0, w, rows, 1, GL_RGBA, GL_FLOAT,
                          GLsizei(row * std::size_t(rows) * sizeof(float)), floats.get());
    // GL rows run bottom-up; the image's top-down.
    for (int r = 0; r < rows; ++r) {
      const float* src = floats.get() + std::size_t(r) * row;
      std::uint8_t* dst = out.data() + std::size_t(h - 1 - (y0 + r)) * row;
      for (std::size_t i = 0; i < row; ++i) dst[i] = toUnorm8(src[i]);
    }
  }
  gl::checkError(gl, "readColorRgba8");
  return out;
}

}  // namespace tg::render
