#version 450 core
#ifdef TG_VIS64
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_NV_shader_atomic_int64 : require
#endif
// The compute glyph path's tile casts (render/compute_glyphs.h): one
// workgroup per 16x16 tile with glyphs, one invocation per pixel. The tile's glyphs are
// sorted by nearest depth in shared memory, kSortBatch at a time (a bitonic
// sort), and each pixel casts those whose rectangle holds it, front to back,
// stopping at the first that lies wholly behind its nearest hit so far,
// which starts as what the visibility buffer already holds (the small
// glyphs the set-up cast, the classes before). The nearest is written to
// the visibility buffer.
#include "lib/compute_vis.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

const uint kSortBatch = 1024u;
const uint kLanes = 256u;
shared uint sNear[kSortBatch];  // orderKey of the nearest view depth (negative in front of an orthographic eye)
shared uint sCandidate[kSortBatch];

// Floats as uints that order as the floats do (negative ones reversed).
uint orderKey(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float fromOrderKey(uint k) { return uintBitsToFloat((k & 0x80000000u) != 0u ? k & 0x7FFFFFFFu : ~k); }

void main() {
  // A workgroup per tile with glyphs (compute_scan.comp's castDispatch).
  uint tile = activeTiles[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x];
  ivec2 p = ivec2(tile % uint(uTilesX), tile / uint(uTilesX)) * kTilePx + ivec2(gl_LocalInvocationID.xy);
  bool inside = all(lessThan(p, ivec2(uViewportDC)));
  uint px = uint(p.y) * uint(uViewportDC.x) + uint(p.x);
  uint b = tileStart[tile], e = min(tileStart[tile + 1u], entryCapacity);
  uint lane = gl_LocalInvocationIndex;
  vec2 fragDC = vec2(p) + 0.5;
  bool hit = false;
  float bestWin = 0.0;
  uint best = 0u;
  // What is in the buffer already bounds the casts. Compared as window
  // depths, which the buffer holds exactly: windowDepthFromViewDepth is
  // monotone in float too (one rounded division), so a glyph whose nearest
  // depth maps below the bound has no hit at or above it.
  uint key = inside ? visKeyAt(px) : kEmptyKey;
  float boundWin = key != kEmptyKey ? uintBitsToFloat(~key) : 0.0;
  for (uint base = b; base < e; base += kSortBatch) {
    uint n = min(kSortBatch, e - base);
    uint size = 2u;
    while (size < n) size <<= 1u;
    for (uint j = lane; j < size; j += kLanes) {
      uint k = j < n ? tileList[base + j] : 0u;
      sCandidate[j] = k;
      sNear[j] = j < n ? orderKey(candidates[k].centreVC_near.w) : 0xFFFFFFFFu;
    }
    barrier();
    for (uint run = 2u; run <= size; run <<= 1u)
      for (uint step = run >> 1u; step > 0u; step >>= 1u) {
        for (uint i = lane; i < size; i += kLanes) {
          uint o = i ^ step;
          if (o > i && (sNear[i] > sNear[o]) == ((i & run) == 0u)) {
            uint t = sNear[i];
            sNear[i] = sNear[o];
            sNear[o] = t;
            t = sCandidate[i];
            sCandidate[i] = sCandidate[o];
            sCandidate[o] = t;
          }
        }
        barrier();
      }
    for (uint j = 0u; inside && j < n; ++j) {
      // Sorted: every later glyph lies behind this one.
      // A perspective depth at or behind the eye has no window depth (its glyph holds the eye).
      float nearVC = fromOrderKey(sNear[j]);
      if ((uOrtho == 1 || nearVC > 0.0) && windowDepthFromViewDepth(nearVC) < max(bestWin, boundWin)) break;
      uint k = sCandidate[j];
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
    barrier();  // the next batch overwrites the shared lists
  }
  if (hit) visWrite(px, bestWin, best);
}
