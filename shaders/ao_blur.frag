#version 450 core
// The depth-aware blur of the raw occlusion (render/ao_pass.h): a 4 x 4
// window, the size of the kernel rotation tile, over pixels of the same
// surface (depth within a fraction of the radius) only, so that occlusion
// does not bleed across silhouettes onto the glyph in front.
#include "lib/bindings.h"
#include "lib/camera.glsl"

layout(binding = TG_UNIT_EFFECT_DEPTH) uniform sampler2D uDepth;
layout(binding = TG_UNIT_AO_RAW) uniform sampler2D uRawAo;

uniform float uRadiusVC;

out float oAo;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float zp = texelFetch(uDepth, p, 0).r;
  oAo = 1.0;
  if (zp <= 0.0) return;  // background
  float dp = viewDepthFromWindowDepth(zp);
  ivec2 size = ivec2(uViewportDC);
  float sum = 0.0, weight = 0.0;
  for (int y = -2; y < 2; ++y)
    for (int x = -2; x < 2; ++x) {
      ivec2 q = clamp(p + ivec2(x, y), ivec2(0), size - 1);
      float zq = texelFetch(uDepth, q, 0).r;
      if (zq <= 0.0) continue;
      float w = max(0.0, 1.0 - abs(viewDepthFromWindowDepth(zq) - dp) / (0.25 * uRadiusVC));
      sum += w * texelFetch(uRawAo, q, 0).r;
      weight += w;
    }
  oAo = sum / weight;  // the centre pixel always counts with weight 1
}
