#version 450 core
// Anti-aliasing (render/antialias_pass.h): one sample's lit colour, added
// (blending ONE, ONE) into the samples' sum where the frame has an edge.
#include "lib/bindings.h"
#include "lib/aa_edge.glsl"

layout(binding = TG_UNIT_AA_SAMPLE) uniform sampler2D uSample;

out vec4 oSum;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (!aaEdge(p)) discard;
  oSum = texelFetch(uSample, p, 0);
}
