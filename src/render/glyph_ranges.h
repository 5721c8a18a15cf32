#pragma once
// The runs the renderer draws and culls, GL-free: each tile's glyphs of one
// dispatch group (tensor::GlyphTile) form a range with the box of its
// centres, so that culling works on compact pieces of space and the two
// programs (ellipsoid, superquadric) each draw a subset of groups.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "tensor/glyph.h"

namespace tg::render {

// std430, mirrored by shaders/lib/glyph_ranges.glsl; 48 bytes, so about
// 0.2 bytes per glyph.
struct GlyphRange {
  float loWC[3];
  float maxAbsEigenvalue;  // the box grows by sqrt(3) * scale * this: the superquadric box's corner
  float hiWC[3];
  float pad0;
  std::uint32_t first, count;
  std::uint32_t pad1[2];
};
static_assert(sizeof(GlyphRange) == 48);

// A contiguous run of glyphs for a direct (not indirect) draw.
struct GlyphRun {
  std::uint32_t first, count;
};

struct RangeTable {
  // Ordered by group, then by tile: the ranges of groups [g0, g1) are the
  // contiguous slice [groupStart[g0], groupStart[g1]).
  std::vector<GlyphRange> ranges;
  std::array<std::uint32_t, 4> groupStart{};
  float minFa = 0;  // a threshold at or below this hides nothing
};

RangeTable buildRanges(const tensor::GlyphSet& set);

// The glyphs of groups [g0, g1) as runs in memory order, adjacent runs
// merged (groups are contiguous within each tile).
std::vector<GlyphRun> groupRuns(const tensor::GlyphSet& set, int g0, int g1);

// The box a range's glyphs can cover at `scale` world units per eigenvalue unit.
void rangeBoxWC(const GlyphRange& r, double scale, glm::dvec3& lo, glm::dvec3& hi);

}  // namespace tg::render
