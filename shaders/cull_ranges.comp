#version 450 core
// Per frame, when the frame needs it: one indirect draw command per range,
// empty when the range's box (grown by its glyphs' extent) is outside the
// view frustum or the slab, else drawing the range's glyphs (all, or the compacted ones).
// The box test mirrors tg::render::boxOutside.
#include "lib/bindings.h"
#include "lib/glyph_ranges.glsl"
#include "lib/camera.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/glyph_size.glsl"

layout(local_size_x = 64) in;

// DrawElementsIndirectCommand for quads; for point sprites the same 20 bytes
// hold a DrawArraysIndirectCommand (count, instanceCount, first, baseInstance)
// and a pad.
struct DrawCommand {
  uint count;
  uint instanceCount;
  uint firstIndex;
  int baseVertex;
  uint baseInstance;
};
layout(std430, binding = TG_SSBO_COMMANDS) writeonly buffer Commands { DrawCommand commands[]; };
layout(std430, binding = TG_SSBO_VISIBLE) buffer Visible { uint visibleGlyphs; };

uniform vec4 uFrustumWC[8];  // six frustum planes, then two slab planes
uniform int uCompacted;
uniform int uRangeCount;
uniform int uPointSprites;

void main() {
  uint k = linearWorkGroup() * 64u + gl_LocalInvocationID.x;
  if (k >= uint(uRangeCount)) return;
  GlyphRange r = ranges[k];
  vec3 lo = r.loWC_maxAbsEigenvalue.xyz, hi = r.hiWC.xyz;
  vec3 centre = 0.5 * (lo + hi);
  // Grown by the glyphs' extent and a little more, so that float rounding of
  // the planes never culls a glyph that the exact test would keep.
  // The largest glyph's radius bounds every glyph's (it is non-decreasing in
  // the magnitude); sqrt(3) of it reaches a superquadric box's corner.
  vec3 halfWC = 0.5 * (hi - lo) + 1.7320508 * glyphRadiusWC(r.loWC_maxAbsEigenvalue.w);
  halfWC += 1e-5 * (abs(centre) + halfWC);
  bool outside = false;
  for (int p = 0; p < 8; ++p) {
    vec4 pl = uFrustumWC[p];
    outside = outside || dot(pl.xyz, centre) + dot(abs(pl.xyz), halfWC) + pl.w < 0.0;
  }
  uint n = outside ? 0u : uCompacted != 0 ? keptCount[k] : r.firstCount.y;
  uint drawn = n > 0u ? 1u : 0u;
  commands[k] = uPointSprites != 0 ? DrawCommand(n, drawn, r.firstCount.x, 0, 0u)
                                   : DrawCommand(6u * n, drawn, 0u, int(4u * r.firstCount.x), 0u);
  if (n > 0u) atomicAdd(visibleGlyphs, n);
}
