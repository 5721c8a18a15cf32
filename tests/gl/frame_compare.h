#pragma once
// Pixel comparisons of two frames of the same camera, for tests that change
// how glyphs are drawn but not what: a pixel differs where its id, depth or
// colour does.
#include <cstddef>

#include "ref/ellipsoid_ref.h"
#include "render/frame_image.h"

namespace tg::test {

inline std::size_t differingPixels(const render::FrameImage& a, const render::FrameImage& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.id.size(); ++i)
    n += a.id[i] != b.id[i] || a.depth[i] != b.depth[i] || a.rgba[4 * i] != b.rgba[4 * i] ||
         a.rgba[4 * i + 1] != b.rgba[4 * i + 1] || a.rgba[4 * i + 2] != b.rgba[4 * i + 2];
  return n;
}

inline std::size_t coveredPixels(const render::FrameImage& a) {
  std::size_t n = 0;
  for (auto id : a.id) n += id != ref::kNoGlyph;
  return n;
}

}  // namespace tg::test
