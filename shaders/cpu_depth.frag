#version 450 core
// The CPU glyph path's casts into a depth-only target: the key light's
// shadow map (render/cpu_glyphs.h), cast from the light as the view is.
// Window depth where a cast hit; elsewhere the cleared map stays.
#include "lib/bindings.h"

layout(binding = TG_UNIT_CPU_DEPTH) uniform sampler2D uWindowDepth;
layout(binding = TG_UNIT_CPU_RECORD) uniform usampler2D uRecord;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (texelFetch(uRecord, p, 0).r == 0u) discard;
  gl_FragDepth = texelFetch(uWindowDepth, p, 0).r;
}
