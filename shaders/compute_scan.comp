#version 450 core
// The compute glyph path's tile offsets (render/compute_glyphs.h): an
// exclusive prefix sum of the tiles' glyph counts into their starts and
// cursors, in one workgroup (the tiles of a 4K frame are 33,000), and the
// indirect dispatch of compute_bin.comp; no CPU round trip.
#include "lib/compute_vis.glsl"

layout(local_size_x = 256) in;

shared uint partial[256];

void main() {
  uint t = gl_LocalInvocationID.x;
  uint n = uint(uTiles);
  uint per = (n + 255u) / 256u;
  uint b = min(n, t * per), e = min(n, b + per);
  uint sum = 0u;
  for (uint j = b; j < e; ++j) sum += tileCount[j];
  partial[t] = sum;
  barrier();
  // Inclusive scan of the 256 partial sums (Hillis and Steele).
  for (uint off = 1u; off < 256u; off <<= 1u) {
    uint v = t >= off ? partial[t - off] : 0u;
    barrier();
    partial[t] += v;
    barrier();
  }
  uint run = partial[t] - sum;
  for (uint j = b; j < e; ++j) {
    tileStart[j] = run;
    tileStart[n + 1u + j] = run;  // compute_bin.comp's cursor
    run += tileCount[j];
  }
  if (t == 255u) {
    uint entries = partial[255];
    tileStart[n] = entries;
    entryCount = entries;
    uint tiled = min(tiledCount, tiledCapacity);
    uint groups = (tiled + 63u) / 64u;
    uint x = min(groups, 65535u);
    binDispatch = uvec4(x, x == 0u ? 0u : (groups + x - 1u) / x, 1u, 0u);
    tiledNeeded = max(tiledNeeded, tiledCount);
    entryNeeded = max(entryNeeded, entries + entryOverflow);
  }
}
