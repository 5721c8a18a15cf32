#version 450 core
// The compute glyph path's resolve (render/compute_glyphs.h) into the
// textures cpu_gbuffer.frag and cpu_depth.frag read, as the CPU path
// uploads them. Without TG_RESOLVE_SURFACE, every pixel's window depth and
// record + 1 (0: empty) from the visibility buffer; with it, per cast
// class and record chunk, the normal and the sign colour's GC hit of the
// pixels whose record is the class's and the chunk's, cast again at the pixel centre with the same code
// (a visibility buffer keeps only which glyph won).
#pragma tg option TG_RESOLVE_SURFACE
#include "lib/compute_vis.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// Image buffers, a texel per pixel, rows bottom first (render/cast_targets.h).
layout(binding = TG_IMAGE_CAST_DEPTH, r32f) uniform writeonly imageBuffer uCastDepth;
layout(binding = TG_IMAGE_CAST_RECORD, r32ui) uniform writeonly uimageBuffer uCastRecord;
layout(binding = TG_IMAGE_CAST_NORMAL, rgba32f) uniform writeonly imageBuffer uCastNormalWC;
layout(binding = TG_IMAGE_CAST_HIT_GC, rgba32f) uniform writeonly imageBuffer uCastHitGC;
uniform int uHitGC;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(uViewportDC)))) return;
  uint px = uint(p.y) * uint(uViewportDC.x) + uint(p.x);
  // Read as 32-bit words: a 64-bit entry's low word is the record.
  uint record = vis[2u * px], key = vis[2u * px + 1u];
#ifndef TG_RESOLVE_SURFACE
  bool empty = key == kEmptyKey;
  imageStore(uCastDepth, int(px), vec4(empty ? 0.0 : uintBitsToFloat(~key)));
  imageStore(uCastRecord, int(px), uvec4(empty ? 0u : record + 1u));
#else
  // Per chunk too: the pixels whose record the bound chunk holds.
  uint k = record - uint(uRecordBase);  // wraps past the chunk for records before it
  if (key == kEmptyKey || k >= uint(uRecordCount) || !inClass(glyphs[k])) return;
  CastCandidate c;
  float depthVC;
  vec3 pGC, gradGC;
  vec3 nWC, hitGC = vec3(0.0);
  if (glyphCandidate(k, c) && castCandidate(vec2(p) + 0.5, c, depthVC, pGC, gradGC)) {
    nWC = candidateNormalWC(c, pGC, gradGC);
    hitGC = candidateHitGC(c, pGC);
  } else {
    // Not reached where the casts and this one compile alike; facing the
    // eye rather than undefined if a compiler rounds them apart.
    vec3 originVC, dirVC;
    rayThroughFragment(vec2(p) + 0.5, originVC, dirVC);
    nWC = normalize(transpose(mat3(uViewWCVC)) * -dirVC);
  }
  imageStore(uCastNormalWC, int(px), vec4(nWC, 0.0));
  if (uHitGC == 1) imageStore(uCastHitGC, int(px), vec4(hitGC, 0.0));
#endif
}
