#version 450 core
// Exact ray-box (three slabs) or, with TG_CYLINDER, ray-cylinder (the
// quadric and its two cap planes) intersection per pixel into the G-buffer
// (lib/prism.glsl). No march: one closed-form span per pixel.
#pragma tg option TG_CYLINDER
#include "lib/camera.glsl"
#include "lib/prism.glsl"
#include "lib/color.glsl"

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
  vec3 originVC, dirVC;
  rayThroughFragment(gl_FragCoord.xy, originVC, dirVC);
  // Restart at the closest approach to the centre, as for ellipsoids: GC
  // coordinates stay O(1) on every ray that can hit.
  float tc = dot(fin.centreVC - originVC, dirVC) / dot(dirVC, dirVC);
  vec3 o = fin.gcFromVC * (originVC + tc * dirVC - fin.centreVC);
  vec3 d = fin.gcFromVC * dirVC;
  vec2 span;
  vec3 nIn, nOut;
#ifdef TG_CYLINDER
  if (!cylinderSpan(o, d, span, nIn, nOut)) discard;
#else
  if (!boxSpan(o, d, span, nIn, nOut)) discard;
#endif
  // First surface at or beyond the near plane: from inside, the far wall.
  bool entry = tc + span.x >= uNearVC;
  float t = entry ? span.x : span.y;
  float depth = tc + t;
  if (!(depth >= uNearVC) || (uOrtho == 1 && depth > uFarVC)) discard;

  vec3 nGC = entry ? nIn : nOut;
  vec3 nVC = transpose(fin.gcFromVC) * nGC;  // inverse transpose of GC -> VC
  vec3 nWC = normalize(transpose(mat3(uViewWCVC)) * nVC);
  gl_FragDepth = windowDepthFromViewDepth(depth);
  oAlbedo = vec4(uColorMode == kColorSign ? signColor(fin.color, o + t * d, fin.gcFromVC) : fin.color, 1.0);
  oNormalWC = vec4(nWC, 0.0);
  oId = fin.id;
}
