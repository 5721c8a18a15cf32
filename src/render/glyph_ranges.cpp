#include "render/glyph_ranges.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tg::render {
namespace {

// Start of group g within tile t, as an offset in the tile; g = 3 is its end.
std::size_t groupOffset(const tensor::GlyphSet& set, std::size_t t, int g) {
  const tensor::GlyphTile& tile = set.tiles[t];
  if (g == 0) return 0;
  if (g == 1) return tile.sphereEnd;
  if (g == 2) return tile.definiteEnd;
  return std::min(tensor::kTileGlyphs, set.glyphs.size() - t * tensor::kTileGlyphs);
}

}  // namespace

RangeTable buildRanges(const tensor::GlyphSet& set) {
  RangeTable table;
  float minFa = std::numeric_limits<float>::infinity();
  for (int g = 0; g < 3; ++g) {
    table.groupStart[std::size_t(g)] = std::uint32_t(table.ranges.size());
    for (std::size_t t = 0; t < set.tiles.size(); ++t) {
      const std::size_t b = t * tensor::kTileGlyphs + groupOffset(set, t, g);
      const std::size_t e = t * tensor::kTileGlyphs + groupOffset(set, t, g + 1);
      if (b == e) continue;
      GlyphRange r{};
      float lo[3], hi[3];
      for (int c = 0; c < 3; ++c) lo[c] = hi[c] = set.glyphs[b].posWC[c];
      float maxAbs = 0;
      for (std::size_t i = b; i < e; ++i) {
        const tensor::GlyphRecord& rec = set.glyphs[i];
        for (int c = 0; c < 3; ++c) {
          lo[c] = std::min(lo[c], rec.posWC[c]);
          hi[c] = std::max(hi[c], rec.posWC[c]);
        }
        maxAbs = std::max({maxAbs, std::abs(rec.eigenvalues[0]), std::abs(rec.eigenvalues[2])});
        minFa = std::min(minFa, rec.fa);
      }
      for (int c = 0; c < 3; ++c) {
        r.loWC[c] = lo[c];
        r.hiWC[c] = hi[c];
      }
      r.maxAbsEigenvalue = maxAbs;
      r.first = std::uint32_t(b);
      r.count = std::uint32_t(e - b);
      table.ranges.push_back(r);
    }
  }
  table.groupStart[3] = std::uint32_t(table.ranges.size());
  table.minFa = set.glyphs.empty() ? 0.0f : minFa;
  return table;
}

std::vector<GlyphRun> groupRuns(const tensor::GlyphSet& set, int g0, int g1) {
  std::vector<GlyphRun> runs;
  for (std::size_t t = 0; t < set.tiles.size(); ++t) {
    const auto b = std::uint32_t(t * tensor::kTileGlyphs + groupOffset(set, t, g0));
    const auto e = std::uint32_t(t * tensor::kTileGlyphs + groupOffset(set, t, g1));
    if (b == e) continue;
    if (!runs.empty() && runs.back().first + runs.back().count == b) runs.back().count += e - b;
    else runs.push_back({b, e - b});
  }
  return runs;
}

void rangeBoxWC(const GlyphRange& r, double scale, glm::dvec3& lo, glm::dvec3& hi) {
  const double pad = std::sqrt(3.0) * scale * double(r.maxAbsEigenvalue);
  lo = glm::dvec3(r.loWC[0], r.loWC[1], r.loWC[2]) - pad;
  hi = glm::dvec3(r.hiWC[0], r.hiWC[1], r.hiWC[2]) + pad;
}

}  // namespace tg::render
