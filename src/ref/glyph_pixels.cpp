#include "ref/glyph_pixels.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace tg::ref {

GlyphPixels countGlyphPixels(std::span<const std::uint32_t> id, std::uint32_t empty) {
  GlyphPixels g;
  g.pixels = id.size();
  std::vector<std::uint32_t> ids;
  for (std::uint32_t v : id)
    if (v != empty) ids.push_back(v);
  g.covered = ids.size();
  std::sort(ids.begin(), ids.end());
  for (std::size_t i = 0; i < ids.size();) {
    std::size_t j = i;
    while (j < ids.size() && ids[j] == ids[i]) ++j;
    ++g.visibleGlyphs;
    g.readableGlyphs += 2.0 * std::sqrt(double(j - i) / std::numbers::pi) >= kReadablePx;
    i = j;
  }
  return g;
}

}  // namespace tg::ref
