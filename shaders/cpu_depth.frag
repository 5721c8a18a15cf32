#version 450 core
// The CPU glyph path's casts into a depth-only target: the key light's
// shadow map (render/cpu_glyphs.h), cast from the light as the view is.
// Window depth where a cast hit; elsewhere the cleared map stays.
#include "lib/bindings.h"

// Buffer textures, a texel per pixel, rows bottom first (render/cast_targets.h).
layout(binding = TG_UNIT_CPU_DEPTH) uniform samplerBuffer uWindowDepth;
layout(binding = TG_UNIT_CPU_RECORD) uniform usamplerBuffer uRecord;
uniform int uCastWidth;

void main() {
  ivec2 xy = ivec2(gl_FragCoord.xy);
  int p = xy.y * uCastWidth + xy.x;
  if (texelFetch(uRecord, p).r == 0u) discard;
  gl_FragDepth = texelFetch(uWindowDepth, p).r;
}
