#version 450 core
// The compute glyph path's tile lists (render/compute_glyphs.h): each tiled
// glyph's index into the lists of the tiles its rectangle touches, at the
// cursors compute_scan.comp set. A list's order is the atomics': the casts
// keep the minimum of (depth, record), which does not depend on it.
#include "lib/compute_vis.glsl"

layout(local_size_x = 64) in;

void main() {
  uint k = linearInvocation(64u);
  if (k >= min(tiledCount, tiledCapacity)) return;
  ivec4 t = candidateRect(candidates[k]) / kTilePx;
  for (int ty = t.y; ty <= t.w; ++ty)
    for (int tx = t.x; tx <= t.z; ++tx) {
      uint slot = atomicAdd(tileStart[uint(uTiles) + 1u + uint(ty * uTilesX + tx)], 1u);
      if (slot < entryCapacity) tileList[slot] = k;
    }
}
