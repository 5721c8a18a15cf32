#include "render/fa_order.h"

#include <stdexcept>
#include <vector>

namespace tg::render {

FaOrder orderByFa(const tensor::GlyphSet& set, std::span<tensor::GlyphRecord> out) {
  const std::size_t n = set.glyphs.size();
  if (out.size() != n) throw std::invalid_argument("orderByFa: output size differs from the glyph count");
  if (set.sphereCount + set.definiteCount > n)
    throw std::invalid_argument("orderByFa: group counts exceed the glyph count");
  FaOrder o;
  const std::size_t end[FaOrder::kGroups] = {set.sphereCount, set.sphereCount + set.definiteCount, n};
  o.groupStart = {0, end[0], end[1]};
  std::vector<std::size_t> cursor(std::size_t(FaOrder::kGroups) * kFaBins, 0);
  for (int g = 0; g < FaOrder::kGroups; ++g) {
    auto& count = o.atLeast[std::size_t(g)];
    for (std::size_t i = o.groupStart[std::size_t(g)]; i < end[g]; ++i) ++count[std::size_t(faBin(set.glyphs[i].fa))];
    // Suffix sums, high bins first in memory: bin b starts after every
    // glyph of a higher bin.
    std::size_t above = 0;
    for (int b = kFaBins - 1; b >= 0; --b) {
      const std::size_t inBin = count[std::size_t(b)];
      cursor[std::size_t(g * kFaBins + b)] = o.groupStart[std::size_t(g)] + above;
      above += inBin;
      count[std::size_t(b)] = above;
    }
    count[kFaBins] = 0;
    for (std::size_t i = o.groupStart[std::size_t(g)]; i < end[g]; ++i)
      out[cursor[std::size_t(g * kFaBins + faBin(set.glyphs[i].fa))]++] = set.glyphs[i];
  }
  return o;
}

}  // namespace tg::render
