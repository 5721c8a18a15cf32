#version 450 core
// Exact ray-ellipsoid intersection per pixel into the G-buffer.
#include "lib/camera.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/color.glsl"

uniform int uColorMode;

in SpriteFS {
  flat vec3 centreVC;
  flat mat3 gcFromVC;
  flat vec3 color;  // with uColorMode kColorSign, the sign weights (lib/color.glsl)
  flat uint id;
} fin;

layout(depth_less) out float gl_FragDepth;
layout(location = 0) out vec4 oAlbedo;
layout(location = 1) out vec4 oNormalWC;
layout(location = 2) out uint oId;

void main() {
  vec3 originVC, dirVC;
  rayThroughFragment(gl_FragCoord.xy, originVC, dirVC);
  // Restart the ray at its closest approach to the centre: on every ray that
  // can hit, GC coordinates are then O(1) even for 1e6:1 glyphs far away.
  float tc = dot(fin.centreVC - originVC, dirVC) / dot(dirVC, dirVC);
  vec3 o = fin.gcFromVC * (originVC + tc * dirVC - fin.centreVC);
  vec3 d = fin.gcFromVC * dirVC;
  float t0, t1;
  if (!unitSphereRoots(o, d, t0, t1)) discard;
  // First surface at or beyond the near plane: from inside, the far wall.
  float t = tc + t0 >= uNearVC ? t0 : t1;
  float depth = tc + t;
  if (!(depth >= uNearVC) || (uOrtho == 1 && depth > uFarVC)) discard;

  vec3 nGC = o + t * d;
  vec3 nVC = transpose(fin.gcFromVC) * nGC;  // inverse transpose of GC -> VC
  vec3 nWC = normalize(transpose(mat3(uViewWCVC)) * nVC);
  gl_FragDepth = windowDepthFromViewDepth(depth);
  oAlbedo = vec4(uColorMode == kColorSign ? signColor(fin.color, nGC, fin.gcFromVC) : fin.color, 1.0);
  oNormalWC = vec4(nWC, 0.0);
  oId = fin.id;
}
