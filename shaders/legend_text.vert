#version 450 core
// The legend's text and lines: triangles from Dear ImGui's draw list
// (render::LegendVertex), in DC pixels with y down from the image's top.
#include "lib/bindings.h"
struct LegendVertex {
  vec4 posUV;  // x, y in pixels; u, v in the font atlas
  vec4 color;  // straight alpha
};
layout(std430, binding = TG_SSBO_LEGEND_VERTICES) readonly buffer LegendVertices { LegendVertex vtx[]; };

uniform vec2 uViewportDC;

out vec2 vUV;
out vec4 vColor;

void main() {
  LegendVertex v = vtx[gl_VertexID];
  vUV = v.posUV.zw;
  vColor = v.color;
  gl_Position = vec4(v.posUV.x / uViewportDC.x * 2.0 - 1.0, 1.0 - v.posUV.y / uViewportDC.y * 2.0, 0.0, 1.0);
}
