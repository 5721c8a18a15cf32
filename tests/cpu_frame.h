#pragma once
// The CPU path's casts as a frame image, for ref::diffImages (tests of
// render::castGlyphs and render::castBlobs).
#include <cmath>

#include "ref/ellipsoid_ref.h"
#include "render/cpu_glyphs.h"
#include "view/frame_image.h"

namespace tg::test {

// The casts as a frame image (rows top first; view depth), for diffImages.
inline render::FrameImage asFrame(const render::CpuCasts& c, const tensor::GlyphSet& set, const render::Camera& cam) {
  render::FrameImage f;
  f.width = c.width;
  f.height = c.height;
  const std::size_t n = std::size_t(c.width) * std::size_t(c.height);
  f.depth.assign(n, INFINITY);
  f.normalWC.assign(3 * n, 0.0f);
  f.id.assign(n, ref::kNoGlyph);
  f.rgba.assign(4 * n, 0.0f);
  for (int j = 0; j < c.height; ++j)
    for (int i = 0; i < c.width; ++i) {
      const std::size_t src = std::size_t(c.height - 1 - j) * std::size_t(c.width) + std::size_t(i);
      const std::size_t dst = std::size_t(j) * std::size_t(c.width) + std::size_t(i);
      if (c.record[src] == 0) continue;
      f.id[dst] = set.glyphs[c.record[src] - 1].id;
      f.depth[dst] = float(cam.viewDepthFromWindowDepth(c.windowDepth[src]));
      for (int k = 0; k < 3; ++k) f.normalWC[3 * dst + std::size_t(k)] = c.normalWC[src][k];
    }
  return f;
}


}  // namespace tg::test
