#pragma once
// Screen tiles for the CPU glyph path (render/cpu_glyphs.h): each glyph's
// pixel rectangle binned to the tiles it touches, in one counting pass over
// all cores, and the worker pool that runs the path's passes.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

namespace tg::render {

inline constexpr int kTilePx = 16;

// Pixel indices, inclusive, in window coordinates (row 0 at the bottom);
// 16 bits each (kMaxCastSide), as a frame keeps one per glyph (2 M glyphs:
// 16 MB).
struct PixelRect {
  std::uint16_t x0, y0, x1, y1;
};
inline constexpr int kMaxCastSide = 65535;
// No pixel: reaches no tile.
inline constexpr PixelRect kNoPixels{65535, 65535, 0, 0};

// The pixel centres (k + 0.5) within rectNDC (xmin, ymin, xmax, ymax), as
// shaders/lib/pixel_centres.glsl's rectMissesEveryPixelCentre maps it;
// false where none lies in the viewport.
// width and height at most kMaxCastSide.
inline bool pixelsOf(const glm::vec4& rectNDC, int width, int height, PixelRect& r) {
  const glm::vec4 dc = (rectNDC + 1.0f) * 0.5f * glm::vec4(float(width), float(height), float(width), float(height));
  const int x0 = std::max(0, int(std::ceil(dc.x - 0.5f))), y0 = std::max(0, int(std::ceil(dc.y - 0.5f)));
  const int x1 = std::min(width - 1, int(std::floor(dc.z - 0.5f))), y1 = std::min(height - 1, int(std::floor(dc.w - 0.5f)));
  if (x0 > x1 || y0 > y1) return false;
  r = {std::uint16_t(x0), std::uint16_t(y0), std::uint16_t(x1), std::uint16_t(y1)};
  return true;
}

// Threads the CPU path runs on: every core the machine reports, at least one.
int cpuPathThreads();

// Runs body(part, parts) once for each part in [0, parts) on its own
// thread (the calling thread runs part 0); returns when all are done and
// rethrows the first exception a part threw.
void runParts(int parts, const std::function<void(int part, int parts)>& body);

// [begin, end) of part `part` of n items split into `parts` contiguous runs.
inline std::size_t partBegin(std::size_t n, int part, int parts) { return n * std::size_t(part) / std::size_t(parts); }

// After runParts wrote part k's kept[k] items to each vector from slot
// partBegin(n, k, parts) on, in order: moves them up to the front, part
// after part, so that the items stay in order; returns how many there are.
// A null vector is skipped.
template <class... Vectors>
std::size_t closeUpParts(const std::vector<std::size_t>& kept, std::size_t n, Vectors*... v) {
  const int parts = int(kept.size());
  std::size_t count = parts > 0 ? kept[0] : 0;
  for (int k = 1; k < parts; ++k) {
    const auto from = std::ptrdiff_t(partBegin(n, k, parts)), to = std::ptrdiff_t(count);
    const std::size_t items = kept[std::size_t(k)];
    ((v ? (void)std::copy_n(v->begin() + from, items, v->begin() + to) : (void)0), ...);
    count += items;
  }
  return count;
}

// keep(i, at) for each i in [0, n), on `parts` threads: each part puts what
// it keeps from slot `at` on, starting at its first index's slot, and says
// whether it kept one; then the parts close up (closeUpParts) so that the
// kept items lie in order at the front of each vector. Returns their count.
template <class Keep, class... Vectors>
std::size_t keepInParts(int parts, std::size_t n, Keep&& keep, Vectors*... v) {
  std::vector<std::size_t> kept(static_cast<std::size_t>(parts), 0);
  runParts(parts, [&](int part, int count) {
    const std::size_t begin = partBegin(n, part, count);
    std::size_t at = begin;
    for (std::size_t i = begin; i < partBegin(n, part + 1, count); ++i)
      if (keep(i, at)) ++at;
    kept[std::size_t(part)] = at - begin;
  });
  return closeUpParts(kept, n, v...);
}

struct TileBins {
  int tilesX = 0, tilesY = 0;
  // Tile t's items are items[start[t] .. start[t + 1]), indices into the
  // binned rectangles in increasing order.
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> items;
  std::size_t tiles() const { return std::size_t(tilesX) * std::size_t(tilesY); }
};

// Bins rects to kTilePx tiles on `parts` threads; each must lie within the
// width x height viewport (the caller's to ensure) or be kNoPixels. Throws
// std::length_error past 2^32 - 1 tile entries.
void binToTiles(std::span<const PixelRect> rects, int width, int height, int parts, TileBins& bins);

// The pixels of the tiles that hold an item, as rectangles: per row of
// tiles, each run of consecutive such tiles, within the width x height
// viewport the bins were made for; rows bottom first. What the CPU path
// writes into GL's targets (shaders/cast_runs.vert), so that the background
// costs no fragments.
void tileRuns(const TileBins& bins, int width, int height, std::vector<PixelRect>& runs);

}  // namespace tg::render
