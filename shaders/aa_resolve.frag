#version 450 core
// Anti-aliasing's resolve (render/antialias_pass.h): the samples' mean where
// the frame has an edge; every other pixel is discarded and keeps the
// frame's own colour, bit for bit.
#include "lib/bindings.h"
#include "lib/aa_edge.glsl"

layout(binding = TG_UNIT_AA_SUM) uniform sampler2D uSum;
uniform float uSamples;

out vec4 oColor;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (!aaEdge(p)) discard;
  oColor = texelFetch(uSum, p, 0) / uSamples;
}
