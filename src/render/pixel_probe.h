#pragma once
// One pixel of the last frame's G-buffer, read without the rest: what
// picking needs (a click or --pick), 8 bytes over the bus instead of a frame.
#include <cmath>
#include <cstdint>

#include "gl/loader.h"
#include "view/camera.h"
#include "render/gbuffer.h"

namespace tg::render {

struct PixelSample {
  std::uint32_t id = 0xFFFFFFFFu;  // as FrameImage::id
  double viewDepth = INFINITY;     // along the view axis from the eye; +inf where empty
};

// Pixel (i, j) of `target` as `cam` drew it; j counts rows from the top, as
// in FrameImage. Throws std::out_of_range outside the target.
PixelSample readPixel(const gl::Api& gl, const Camera& cam, const GBuffer& target, int i, int j);

}  // namespace tg::render
