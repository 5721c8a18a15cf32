#version 450 core
#ifdef TG_VIS64
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_NV_shader_atomic_int64 : require
#endif
// The compute glyph path's tile casts (render/compute_glyphs.h): one
// workgroup per 16x16 tile, one invocation per pixel, each pixel cast
// against the tile's glyphs whose rectangle holds it, skipping those that
// lie wholly behind its nearest hit so far; the nearest is written to the
// visibility buffer, where the directly cast small glyphs are too.
#include "lib/compute_vis.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

void main() {
  ivec2 p = ivec2(gl_WorkGroupID.xy) * kTilePx + ivec2(gl_LocalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(uViewportDC)))) return;
  uint tile = gl_WorkGroupID.y * uint(uTilesX) + gl_WorkGroupID.x;
  uint b = tileStart[tile], e = min(tileStart[tile + 1u], entryCapacity);
  vec2 fragDC = vec2(p) + 0.5;
  bool hit = false;
  float bestWin = 0.0, bestVC = 1.0 / 0.0;
  uint best = 0u;
  for (uint j = b; j < e; ++j) {
    uint k = tileList[j];
    uvec4 rr = candidates[k].record_rect;
    ivec4 r = ivec4(rr.y & 0xFFFFu, rr.y >> 16, rr.z & 0xFFFFu, rr.z >> 16);
    if (p.x < r.x || p.y < r.y || p.x > r.z || p.y > r.w) continue;
    CastCandidate c = candidates[k];
    if (c.centreVC_near.w > bestVC) continue;
    float depthVC;
    vec3 pGC, gradGC;
    if (!castCandidate(fragDC, c, depthVC, pGC, gradGC)) continue;
    float win = windowDepthFromViewDepth(depthVC);
    if (!hit || win > bestWin || (win == bestWin && rr.x < best)) {
      hit = true;
      bestWin = win;
      bestVC = depthVC;
      best = rr.x;
    }
  }
  if (hit) visWrite(uint(p.y) * uint(uViewportDC.x) + uint(p.x), bestWin, best);
}
