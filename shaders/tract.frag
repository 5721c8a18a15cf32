#version 450 core
// Tracts into the G-buffer (render/tract_item.h), shaded as tubes: across
// the quad the normal turns from one side through the eye direction to the
// other, and the depth is the tube's front surface, nearer than the quad by
// up to its radius (reversed Z: greater is nearer), so that glyphs and
// tracts meet where their surfaces do. Colour: the direction of the
// streamline there (|x| red, |y| green, |z| blue), or the item's colour.
#include "lib/bindings.h"
#include "lib/camera.glsl"

layout(depth_greater) out float gl_FragDepth;

in TractFS {
  vec3 posVC;
  vec3 tangentWC;
  float across;
  float radiusVC;
} fin;

uniform vec3 uColor;
uniform int uByDirection;
uniform int uId;  // the id's bits
layout(location = 0) out vec4 oAlbedo;
layout(location = 1) out vec4 oNormalWC;
layout(location = 2) out uint oId;

void main() {
  float s = clamp(fin.across, -1.0, 1.0), c = sqrt(max(0.0, 1.0 - s * s));
  vec3 toEye = uOrtho == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-fin.posVC);
  vec3 side = cross(mat3(uViewWCVC) * fin.tangentWC, toEye);
  float sideLen = length(side);
  vec3 n = (sideLen > 1e-20 ? s / sideLen * side : vec3(0.0)) + c * toEye;
  vec3 nVC = dot(n, n) > 1e-12 ? normalize(n) : toEye;
  vec3 surfVC = fin.posVC + toEye * (fin.radiusVC * c);
  gl_FragDepth = windowDepthFromViewDepth(uOrtho == 1 ? -surfVC.z : max(-surfVC.z, uNearVC));
  float len = length(fin.tangentWC);
  vec3 dir = len > 0.0 ? abs(fin.tangentWC) / len : vec3(1.0);
  oAlbedo = vec4(uByDirection == 1 ? dir : uColor, 1.0);
  oNormalWC = vec4(normalize(transpose(mat3(uViewWCVC)) * nVC), 0.0);
  oId = uint(uId);
}
