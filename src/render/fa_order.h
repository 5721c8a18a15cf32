#pragma once
// The GPU order of glyph records: within each dispatch group (spheres,
// definite, mixed-sign; see tensor::GlyphSet), descending FA in 256 bins, so
// that an FA threshold is a draw-count prefix per group (as Kindlmann's Deft
// sorts by anisotropy). Culled glyphs then cost no vertex work at all; the
// fragment stages still test FA exactly, so the bins only need to be
// conservative, never exact.
#include <array>
#include <cstddef>
#include <span>

#include "tensor/glyph.h"

namespace tg::render {

inline constexpr int kFaBins = 256;

// Bin of an FA value: monotonic, [0, 1) spread over bins 0..254, FA >= 1
// (indefinite tensors reach past 1) in bin 255, NaN in bin 0.
inline int faBin(float fa) {
  if (fa >= 1.0f) return kFaBins - 1;
  if (!(fa > 0.0f)) return 0;
  const int b = int(fa * float(kFaBins - 1));
  return b < kFaBins - 2 ? b : kFaBins - 2;
}

struct FaOrder {
  static constexpr int kGroups = 3;
  std::array<std::size_t, kGroups> groupStart{};
  // atLeast[g][b]: glyphs of group g in bins >= b, i.e. the count to draw
  // from groupStart[g] for a threshold in bin b. atLeast[g][kFaBins] = 0.
  std::array<std::array<std::size_t, kFaBins + 1>, kGroups> atLeast{};

  // Glyphs to draw from group g for FA threshold faMin: all with FA >= faMin,
  // plus at most those sharing faMin's bin.
  std::size_t drawCount(int g, float faMin) const { return atLeast[std::size_t(g)][std::size_t(faBin(faMin))]; }
};

// Writes set.glyphs into `out` (same size) in FA order and returns the
// table. One counting pass and one scatter: O(n), no extra record buffer,
// so it can write straight into a mapped GL buffer.
FaOrder orderByFa(const tensor::GlyphSet& set, std::span<tensor::GlyphRecord> out);

}  // namespace tg::render
