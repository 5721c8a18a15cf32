#pragma once
// Screen tiles for the CPU glyph path (render/cpu_glyphs.h): each glyph's
// pixel rectangle binned to the tiles it touches, in one counting pass over
// all cores, and the worker pool that runs the path's passes.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace tg::render {

inline constexpr int kTilePx = 16;

// Pixel indices, inclusive, in window coordinates (row 0 at the bottom).
struct PixelRect {
  int x0, y0, x1, y1;
};

// Threads the CPU path runs on: every core the machine reports, at least one.
int cpuPathThreads();

// Runs body(part, parts) once for each part in [0, parts) on its own
// thread (the calling thread runs part 0); returns when all are done and
// rethrows the first exception a part threw.
void runParts(int parts, const std::function<void(int part, int parts)>& body);

// [begin, end) of part `part` of n items split into `parts` contiguous runs.
inline std::size_t partBegin(std::size_t n, int part, int parts) { return n * std::size_t(part) / std::size_t(parts); }

struct TileBins {
  int tilesX = 0, tilesY = 0;
  // Tile t's items are items[start[t] .. start[t + 1]), indices into the
  // binned rectangles in increasing order.
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> items;
  std::size_t tiles() const { return std::size_t(tilesX) * std::size_t(tilesY); }
};

// Bins rects to kTilePx tiles on `parts` threads; each must lie within the
// width x height viewport and be non-empty (the caller's to ensure). Throws
// std::length_error past 2^32 - 1 tile entries.
void binToTiles(std::span<const PixelRect> rects, int width, int height, int parts, TileBins& bins);

}  // namespace tg::render
