#version 450 core
// Exact ray-box (three slabs) or, with TG_CYLINDER, ray-cylinder (the
// quadric and its two cap planes) intersection per pixel into the G-buffer
// (lib/prism.glsl's castPrism, which the CPU glyph path runs too). No
// march: one closed-form span per pixel.
#pragma tg option TG_CYLINDER
#include "lib/camera.glsl"
#include "lib/glyph_record_type.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/glyph_size.glsl"
#include "lib/selection.glsl"
#include "lib/prism.glsl"
#include "lib/color.glsl"

#ifdef TG_CYLINDER
const bool kCylinder = true;
#else
const bool kCylinder = false;
#endif

uniform int uColorMode;

in PrismFS {
  flat vec3 centreVC;
  flat mat3 gcFromVC;
  flat vec3 color;
  flat uint id;
} fin;

layout(depth_less) out float gl_FragDepth;
layout(location = 0) out vec4 oAlbedo;
layout(location = 1) out vec4 oNormalWC;
layout(location = 2) out uint oId;

void main() {
  float depth;
  vec3 pGC, nGC;
  if (!castPrism(gl_FragCoord.xy, fin.centreVC, fin.gcFromVC, kCylinder, depth, pGC, nGC)) discard;
  gl_FragDepth = windowDepthFromViewDepth(depth);
  oAlbedo = vec4(uColorMode == kColorSign ? signColor(fin.color, pGC, fin.gcFromVC) : fin.color, 1.0);
  oNormalWC = vec4(prismNormalWC(fin.gcFromVC, nGC), 0.0);
  oId = fin.id;
}
