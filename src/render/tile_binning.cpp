#include "render/tile_binning.h"

#include <algorithm>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace tg::render {

int cpuPathThreads() { return int(std::max(1u, std::thread::hardware_concurrency())); }

void runParts(int parts, const std::function<void(int, int)>& body) {
  std::exception_ptr first;
  std::mutex m;
  auto run = [&](int part) {
    try {
      body(part, parts);
    } catch (...) {
      const std::lock_guard lock(m);
      if (!first) first = std::current_exception();
    }
  };
  {
    std::vector<std::jthread> pool;
    pool.reserve(std::size_t(std::max(parts - 1, 0)));
    for (int k = 1; k < parts; ++k) pool.emplace_back(run, k);
    run(0);
  }
  if (first) std::rethrow_exception(first);
}

void binToTiles(std::span<const PixelRect> rects, int width, int height, int parts, TileBins& bins) {
  bins.tilesX = (width + kTilePx - 1) / kTilePx;
  bins.tilesY = (height + kTilePx - 1) / kTilePx;
  const std::size_t tiles = bins.tiles();
  // counts[part * tiles + t]: part's entries in tile t, then their offsets.
  std::vector<std::uint64_t> counts(std::size_t(parts) * tiles, 0);
  const std::size_t n = rects.size();
  auto forTiles = [&](const PixelRect& r, auto&& f) {
    for (int ty = r.y0 / kTilePx; ty <= r.y1 / kTilePx; ++ty)
      for (int tx = r.x0 / kTilePx; tx <= r.x1 / kTilePx; ++tx) f(std::size_t(ty) * std::size_t(bins.tilesX) + std::size_t(tx));
  };
  runParts(parts, [&](int part, int np) {
    std::uint64_t* c = counts.data() + std::size_t(part) * tiles;
    for (std::size_t i = partBegin(n, part, np); i < partBegin(n, part + 1, np); ++i)
      forTiles(rects[i], [&](std::size_t t) { ++c[t]; });
  });
  // Offsets tile by tile, parts in order within a tile: each tile's items
  // then run in increasing index order.
  bins.start.assign(tiles + 1, 0);
  std::uint64_t total = 0;
  for (std::size_t t = 0; t < tiles; ++t) {
    bins.start[t] = std::uint32_t(total);
    for (int part = 0; part < parts; ++part) {
      std::uint64_t& c = counts[std::size_t(part) * tiles + t];
      const std::uint64_t k = c;
      c = total;
      total += k;
    }
    if (total > std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("binToTiles: more than 2^32 - 1 glyph-tile entries");
  }
  bins.start[tiles] = std::uint32_t(total);
  bins.items.resize(std::size_t(total));
  runParts(parts, [&](int part, int np) {
    std::uint64_t* c = counts.data() + std::size_t(part) * tiles;
    for (std::size_t i = partBegin(n, part, np); i < partBegin(n, part + 1, np); ++i)
      forTiles(rects[i], [&](std::size_t t) { bins.items[std::size_t(c[t]++)] = std::uint32_t(i); });
  });
}

void tileRuns(const TileBins& bins, int width, int height, std::vector<PixelRect>& runs) {
  runs.clear();
  for (int ty = 0; ty < bins.tilesY; ++ty)
    for (int tx = 0; tx < bins.tilesX;) {
      auto holds = [&](int x) {
        const std::size_t t = std::size_t(ty) * std::size_t(bins.tilesX) + std::size_t(x);
        return bins.start[t] != bins.start[t + 1];
      };
      if (!holds(tx)) {
        ++tx;
        continue;
      }
      const int first = tx;
      while (tx < bins.tilesX && holds(tx)) ++tx;
      runs.push_back({std::uint16_t(first * kTilePx), std::uint16_t(ty * kTilePx),
                      std::uint16_t(std::min(width, tx * kTilePx) - 1), std::uint16_t(std::min(height, (ty + 1) * kTilePx) - 1)});
    }
}

}  // namespace tg::render
