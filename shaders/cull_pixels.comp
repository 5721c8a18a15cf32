#version 450 core
// llvmpipe only, per frame while glyphs are about a pixel or smaller
// (render/sprite_primitive.h): each range's glyphs that pass the selection
// and whose bounding sphere's screen rectangle holds a pixel centre, in
// input order, into the kept list that the draw walks (as compact_fa.comp's).
// The vertex stage would drop every other glyph itself, but llvmpipe runs it
// on one thread, eight glyphs a lane group, where one kept glyph holds the
// other seven; this pass runs on every thread and lets the vertex stage see
// only the kept ones. One invocation walks a whole range: no barriers, which
// llvmpipe's compute threads pay dearly for.
#include "lib/bindings.h"
#include "lib/camera.glsl"
#include "lib/glyph_record.glsl"
#include "lib/glyph_ranges.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/glyph_size.glsl"
#include "lib/selection.glsl"
#include "lib/pixel_centres.glsl"

layout(local_size_x = 8) in;
layout(std430, binding = TG_SSBO_KEPT_INDEX) writeonly buffer KeptIndex { uint keptIndex[]; };

uniform int uRangeCount;

void main() {
  uint k = linearWorkGroup() * 8u + gl_LocalInvocationID.x;
  if (k >= uint(uRangeCount)) return;
  uvec4 fc = ranges[k].firstCount;
  uint kept = 0u;
  for (uint i = fc.x; i < fc.x + fc.y; ++i) {
    vec4 posWC_fa = glyphs[i].posWC_fa;
    if (!glyphSelected(posWC_fa)) continue;
    vec3 axes = glyphAxes(glyphs[i].eigenvalues_id.xyz);
    if (!(max(axes.x, max(axes.y, axes.z)) > 0.0)) continue;
    // The box's half-diagonal: every kind's glyph lies within it.
    vec3 centreVC = (uViewWCVC * vec4(posWC_fa.xyz, 1.0)).xyz;
    if (spriteMissesEveryPixelCentre(centreVC, length(axes))) continue;
    keptIndex[fc.x + kept] = i;
    ++kept;
  }
  keptCount[k] = kept;
}
