#version 450 core
// Writes the G-buffer's depth attachment from a float window-depth channel
// (reversed; 0: nothing) that a glyph path filled by a compute shader or
// from the CPU (render/depth_resolve.h). Colour writes are masked off.
#include "lib/bindings.h"

layout(binding = TG_UNIT_RESOLVE_DEPTH) uniform sampler2D uWindowDepth;

void main() { gl_FragDepth = texelFetch(uWindowDepth, ivec2(gl_FragCoord.xy), 0).r; }
