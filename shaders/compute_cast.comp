#version 450 core
#ifdef TG_VIS64
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_NV_shader_atomic_int64 : require
#endif
// The compute glyph path's tile casts (render/compute_glyphs.h): one
// workgroup per 16x16 tile with glyphs, one invocation per pixel, each pixel
// cast against the tile's glyphs whose rectangle holds it. The list comes
// in runs sorted by nearest depth (compute_sort.comp): within a run, the
// first glyph that lies wholly behind the pixel's nearest hit so far ends
// the run, the hit bounded also by what the visibility buffer holds (the
// small glyphs the set-up cast, the classes before). The nearest is written
// to the visibility buffer.
#include "lib/compute_vis.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

void main() {
  uint tile = activeTiles[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x];
  ivec2 p = ivec2(tile % uint(uTilesX), tile / uint(uTilesX)) * kTilePx + ivec2(gl_LocalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(uViewportDC)))) return;
  uint px = uint(p.y) * uint(uViewportDC.x) + uint(p.x);
  uint b = tileStart[tile], e = min(tileStart[tile + 1u], entryCapacity);
  vec2 fragDC = vec2(p) + 0.5;
  bool hit = false;
  float bestWin = 0.0;
  uint best = 0u;
  // Compared as window depths, which the buffer holds exactly:
  // windowDepthFromViewDepth is monotone in float too (one rounded
  // division), so a glyph whose nearest depth maps below the bound has no
  // hit at or above it.
  uint key = visKeyAt(px);
  float boundWin = key != kEmptyKey ? uintBitsToFloat(~key) : 0.0;
  // A run's rest is skipped by a flag: one loop over the list, with no
  // jump in its index.
  bool behind = false;
  for (uint j = b; j < e; ++j) {
    if ((j - b) % kSortRun == 0u) behind = false;  // a new sorted run
    if (behind) continue;
    bool sorted = (j - b) / kSortRun < kSortRunsMax;
    uint k = tileList[j];
    float nearest = candidates[k].centreVC_near.w;
    // The sprite's nearest depth, less a ten-thousandth: a hit at a
    // glyph's nearest point may round in front of it, and skipping the
    // glyph that holds the buffer's depth loses the pixel's record in the
    // two-pass buffer's second pass.
    float nearVC = nearest - 1e-4 * (abs(nearest) + (uOrtho == 1 ? uFarVC - uNearVC : 0.0));
    // A perspective depth at or behind the eye has no window depth (its glyph holds the eye).
    if (sorted && (uOrtho == 1 || nearVC > 0.0) && windowDepthFromViewDepth(nearVC) < max(bestWin, boundWin)) {
      behind = true;  // the rest of this run lies behind too
      continue;
    }
    uvec4 rr = candidates[k].record_rect;
    ivec4 r = ivec4(rr.y & 0xFFFFu, rr.y >> 16, rr.z & 0xFFFFu, rr.z >> 16);
    if (p.x < r.x || p.y < r.y || p.x > r.z || p.y > r.w) continue;
    CastCandidate c = candidates[k];
    float depthVC;
    vec3 pGC, gradGC;
    if (!castCandidate(fragDC, c, depthVC, pGC, gradGC)) continue;
    float win = windowDepthFromViewDepth(depthVC);
    if (!hit || win > bestWin || (win == bestWin && rr.x < best)) {
      hit = true;
      bestWin = win;
      best = rr.x;
    }
  }
  if (hit) visWrite(px, bestWin, best);
}
