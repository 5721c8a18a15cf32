#include "render/pixel_probe.h"

#include <stdexcept>
#include <string>

namespace tg::render {

PixelSample readPixel(const gl::Api& gl, const Camera& cam, const GBuffer& target, int i, int j) {
  if (i < 0 || j < 0 || i >= target.width() || j >= target.height())
    throw std::out_of_range("readPixel: pixel (" + std::to_string(i) + ", " + std::to_string(j) + ") is outside the " +
                            std::to_string(target.width()) + " x " + std::to_string(target.height()) + " frame");
  const int row = target.height() - 1 - j;  // GL rows run bottom-up
  PixelSample s;
  float windowDepth = 0.0f;
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.GetTextureSubImage(target.id(), 0, i, row, 0, 1, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, sizeof(s.id), &s.id);
  gl.GetTextureSubImage(target.depth(), 0, i, row, 0, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, sizeof(windowDepth),
                        &windowDepth);
  gl::checkError(gl, "readPixel");
  // As readback(): the depth buffer is cleared, not empty, where nothing was drawn.
  s.viewDepth = s.id == 0xFFFFFFFFu ? INFINITY : cam.viewDepthFromWindowDepth(double(windowDepth));
  return s;
}

}  // namespace tg::render
