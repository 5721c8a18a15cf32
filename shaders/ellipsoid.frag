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
  float depth;
  vec3 nGC;
  if (!castEllipsoid(gl_FragCoord.xy, fin.centreVC, fin.gcFromVC, depth, nGC)) discard;
  gl_FragDepth = windowDepthFromViewDepth(depth);
  oAlbedo = vec4(uColorMode == kColorSign ? signColor(fin.color, nGC, fin.gcFromVC) : fin.color, 1.0);
  oNormalWC = vec4(ellipsoidNormalWC(fin.gcFromVC, nGC), 0.0);
  oId = fin.id;
}
