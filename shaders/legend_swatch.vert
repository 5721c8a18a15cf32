#version 450 core
// A rectangle given in DC pixels, y down from the image's top (render/legend_layout.h).
uniform vec2 uViewportDC;
uniform vec4 uRectDC;  // x0, y0, x1, y1

void main() {
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);  // a 4-vertex triangle strip
  vec2 pDC = mix(uRectDC.xy, uRectDC.zw, corner);
  gl_Position = vec4(pDC.x / uViewportDC.x * 2.0 - 1.0, 1.0 - pDC.y / uViewportDC.y * 2.0, 0.0, 1.0);
}
