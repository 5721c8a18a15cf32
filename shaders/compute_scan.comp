#version 450 core
// The compute glyph path's tile offsets (render/compute_glyphs.h): an
// exclusive prefix sum of the tiles' glyph counts into their starts and
// cursors, and of their being non-empty into the list of tiles to cast, in
// one workgroup (the tiles of a 4K frame are 33,000); then the indirect
// dispatches of compute_bin.comp, compute_sort.comp (by the most entries of
// a tile) and compute_cast.comp. No CPU round trip.
#include "lib/compute_vis.glsl"

layout(local_size_x = 256) in;

shared uint partial[256];
shared uint partialTiles[256];
shared uint partialMax[256];  // the most entries of a tile

void main() {
  uint t = gl_LocalInvocationID.x;
  uint n = uint(uTiles);
  uint per = (n + 255u) / 256u;
  uint b = min(n, t * per), e = min(n, b + per);
  uint sum = 0u, tiles = 0u, most = 0u;
  for (uint j = b; j < e; ++j) {
    sum += tileCount[j];
    tiles += tileCount[j] > 0u ? 1u : 0u;
    most = max(most, tileCount[j]);
  }
  partial[t] = sum;
  partialTiles[t] = tiles;
  partialMax[t] = most;
  barrier();
  // Inclusive scans of the 256 partial sums (Hillis and Steele).
  for (uint off = 1u; off < 256u; off <<= 1u) {
    uint v = t >= off ? partial[t - off] : 0u;
    uint w = t >= off ? partialTiles[t - off] : 0u;
    uint m = t >= off ? partialMax[t - off] : 0u;
    barrier();
    partial[t] += v;
    partialTiles[t] += w;
    partialMax[t] = max(partialMax[t], m);
    barrier();
  }
  uint run = partial[t] - sum, slot = partialTiles[t] - tiles;
  for (uint j = b; j < e; ++j) {
    tileStart[j] = run;
    tileStart[n + 1u + j] = run;  // compute_bin.comp's cursor
    run += tileCount[j];
    if (tileCount[j] > 0u) activeTiles[slot++] = j;
  }
  if (t == 255u) {
    uint entries = partial[255];
    tileStart[n] = entries;
    entryCount = entries;
    uint tiled = min(tiledCount, tiledCapacity);
    binDispatch = dispatchOver((tiled + 63u) / 64u);
    castDispatch = dispatchOver(partialTiles[255]);
    // x and z the active tiles (as dispatchOver's x and y), y the runs.
    uvec4 overTiles = dispatchOver(partialTiles[255]);
    uint runs = (min(partialMax[255], entryCapacity) + kSortRun - 1u) / kSortRun;
    sortDispatch = uvec4(overTiles.x, min(runs, kSortRunsMax), overTiles.y, 0u);
    tiledNeeded = max(tiledNeeded, tiledCount);
    entryNeeded = max(entryNeeded, entries + entryOverflow);
  }
}
