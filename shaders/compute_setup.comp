#version 450 core
#ifdef TG_VIS64
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_NV_shader_atomic_int64 : require
#endif
// The compute glyph path's set-up (render/compute_glyphs.h), one invocation
// per record of the bound chunk's kept batches (compute_batches.comp) in the
// class's groups: the sprite stage's culls and screen
// rectangle; a glyph of at most kDirectPixels pixel centres is cast at each
// of them here and written to the visibility buffer, a larger one is kept
// for the tiles (compute_scan.comp, compute_bin.comp, compute_cast.comp).
#include "lib/compute_vis.glsl"

layout(local_size_x = 64) in;

// Glyphs about a pixel or smaller, most of a dense far field, cost one
// invocation and no tile entries.
const int kDirectPixels = 16;

void main() {
  uint k = keptRecord(64u);
  if (k >= uint(uRecordCount) || !inClass(glyphs[k])) return;
  CastCandidate c;
  if (!glyphCandidate(k, c)) return;
  uint i = c.record_rect.x;
  if (uPass == 0) atomicAdd(drawn, 1u);
  ivec4 r = candidateRect(c);
  if ((r.z - r.x + 1) * (r.w - r.y + 1) <= kDirectPixels) {
    for (int y = r.y; y <= r.w; ++y)
      for (int x = r.x; x <= r.z; ++x) {
        float depthVC;
        vec3 pGC, gradGC;
        if (castCandidate(vec2(x, y) + 0.5, c, depthVC, pGC, gradGC))
          visWrite(uint(y) * uint(uViewportDC.x) + uint(x), windowDepthFromViewDepth(depthVC), i);
      }
    return;
  }
  ivec4 t = r / kTilePx;
  uint slot = atomicAdd(tiledCount, 1u);
  if (slot >= tiledCapacity) {
    // Counted: the frame is cast again with room for it and its entries.
    atomicAdd(entryOverflow, uint((t.z - t.x + 1) * (t.w - t.y + 1)));
    return;
  }
  candidates[slot] = c;
  for (int ty = t.y; ty <= t.w; ++ty)
    for (int tx = t.x; tx <= t.z; ++tx) atomicAdd(tileCount[ty * uTilesX + tx], 1u);
}
