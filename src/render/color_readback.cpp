#include "render/color_readback.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "view/frame_image.h"

namespace tg::render {

namespace {

// GL rows run bottom-up; FrameImage rows top-down.
template <class T>
void flipRows(std::vector<T>& v, int width, int height, int channels) {
  const std::size_t row = std::size_t(width) * channels;
  for (int j = 0; j < height / 2; ++j)
    std::swap_ranges(v.begin() + std::ptrdiff_t(j * row), v.begin() + std::ptrdiff_t((j + 1) * row),
                     v.begin() + std::ptrdiff_t((height - 1 - j) * row));
}

}  // namespace

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

// Reads each channel straight into its final array: no staging copies, so a
// PNG frame costs 16 bytes per pixel on the CPU and an EXR frame 36.
FrameImage readFrame(const gl::Api& gl, const Camera& cam, const GBuffer& t, Channels channels) {
  FrameImage img;
  const int w = t.width(), h = t.height();
  img.width = w;
  img.height = h;
  const std::size_t n = std::size_t(w) * h;
  auto bytes = [](const auto& v) { return GLsizei(v.size() * sizeof(v[0])); };
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  if (channels == Channels::Rgba8) {
    img.rgba8 = readColorRgba8(gl, t);
    return img;
  }
  img.rgba.resize(4 * n);
  gl.GetTextureImage(t.color(), 0, GL_RGBA, GL_FLOAT, bytes(img.rgba), img.rgba.data());
  flipRows(img.rgba, w, h, 4);
  if (channels == Channels::All) {
    img.id.resize(n);
    img.depth.resize(n);
    img.normalWC.resize(3 * n);
    gl.GetTextureImage(t.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, bytes(img.id), img.id.data());
    gl.GetTextureImage(t.depth(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, bytes(img.depth), img.depth.data());
    gl.GetTextureImage(t.normalWC(), 0, GL_RGB, GL_FLOAT, bytes(img.normalWC), img.normalWC.data());
    flipRows(img.id, w, h, 1);
    flipRows(img.depth, w, h, 1);
    flipRows(img.normalWC, w, h, 3);
    for (std::size_t i = 0; i < n; ++i) {
      const bool empty = img.id[i] == 0xFFFFFFFFu;
      img.depth[i] = empty ? INFINITY : float(cam.viewDepthFromWindowDepth(img.depth[i]));
      if (empty) img.normalWC[3 * i] = img.normalWC[3 * i + 1] = img.normalWC[3 * i + 2] = 0.0f;
    }
  }
  gl::checkError(gl, "GlyphRenderer::readback");
  return img;
}

}  // namespace tg::render
