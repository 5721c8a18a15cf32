#version 450 core
// Anti-aliasing's edge mask (render/antialias_pass.h): the pixels whose 3x3
// block of ids holds another id (lib/aa_edge.glsl) keep the fullscreen
// triangle's depth; the coverage pass then runs at those alone.
#include "lib/bindings.h"
#include "lib/aa_edge.glsl"

void main() {
  if (!aaEdge(ivec2(gl_FragCoord.xy))) discard;
}
