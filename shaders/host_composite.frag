#version 450 core
// Copies the lit glyphs into a host application's framebuffer (the ParaView
// plugin, plugins/paraview): the colour, and the depth re-projected into the
// host's convention, so that the host's own geometry and the glyphs hide each
// other correctly. Pixels without a glyph are discarded.
#include "lib/camera.glsl"

layout(binding = 0) uniform sampler2D uColor;
layout(binding = 1) uniform sampler2D uDepth;  // reversed window depth
layout(binding = 2) uniform usampler2D uId;

uniform vec2 uOriginDC;   // the host viewport's lower-left corner, pixels
uniform vec4 uHostZRow;   // rows 2 and 3 of the host's view -> clip matrix
uniform vec4 uHostWRow;

out vec4 oColor;

const uint kNoGlyph = 0xFFFFFFFFu;

void main() {
  vec2 fragDC = gl_FragCoord.xy - uOriginDC;
  ivec2 p = ivec2(fragDC);
  if (texelFetch(uId, p, 0).r == kNoGlyph) discard;
  vec3 originVC, dirVC;
  rayThroughFragment(fragDC, originVC, dirVC);
  vec4 pVC = vec4(originVC + viewDepthFromWindowDepth(texelFetch(uDepth, p, 0).r) * dirVC, 1.0);
  // The host's clip depth; glDepthRange(0, 1) maps [-1, 1] to [0, 1].
  gl_FragDepth = clamp(0.5 * dot(uHostZRow, pVC) / dot(uHostWRow, pVC) + 0.5, 0.0, 1.0);
  oColor = vec4(texelFetch(uColor, p, 0).rgb, 1.0);
}
