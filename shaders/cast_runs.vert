#version 450 core
// The CPU glyph path's writes into GL's targets (cpu_gbuffer.frag,
// cpu_depth.frag) over only the rows of tiles that glyphs reach
// (render/tile_binning.h, tileRuns): on llvmpipe a full-screen pass costs
// its fragments wherever the casts left the background. Six vertices a run:
// two triangles over its pixels, edges on pixel boundaries, so that each
// pixel centre is covered once.
#include "lib/bindings.h"

// Run k: (x0 | y0 << 16, x1 | y1 << 16), pixels inclusive.
layout(binding = TG_UNIT_CPU_RUNS) uniform usamplerBuffer uRuns;
uniform vec2 uRunViewportDC;

void main() {
  uvec2 run = texelFetch(uRuns, gl_VertexID / 6).xy;
  const vec2 corners[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(0.0, 1.0), vec2(0.0, 1.0), vec2(1.0, 0.0),
                                  vec2(1.0, 1.0));
  vec2 lo = vec2(run.x & 0xffffu, run.x >> 16u), hi = vec2(run.y & 0xffffu, run.y >> 16u) + 1.0;
  vec2 pDC = mix(lo, hi, corners[gl_VertexID % 6]);
  gl_Position = vec4(pDC / uRunViewportDC * 2.0 - 1.0, 0.0, 1.0);
}
