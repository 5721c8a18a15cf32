#version 450 core
// Context meshes into the G-buffer (flat normals, the item's colour and id),
// or with TG_MESH_FORWARD lit here and blended over the lit image: the
// see-through mode's front layer (render/mesh_item.h).
#include "lib/bindings.h"
#include "lib/camera.glsl"

in MeshFS {
  vec3 posVC;
} fin;

uniform vec3 uColor;
uniform int uEdges;  // 1: lines, whose normal faces the eye

// Unit normal towards the eye: the triangle's own plane from the position's
// screen derivatives, which are exact for a flat triangle.
vec3 facingNormalVC() {
  vec3 toEyeVC = uOrtho == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-fin.posVC);
  if (uEdges == 1) return toEyeVC;
  vec3 n = cross(dFdx(fin.posVC), dFdy(fin.posVC));
  float len = length(n);
  n = len > 0.0 ? n / len : toEyeVC;
  return dot(n, toEyeVC) < 0.0 ? -n : n;
}

#pragma tg option TG_MESH_FORWARD
#ifdef TG_MESH_FORWARD
layout(binding = TG_UNIT_MESH_SCENE_DEPTH) uniform sampler2D uSceneDepth;  // the opaque scene, reversed
uniform vec3 uKeyDirVC;
uniform vec4 uLightMix;  // ambient, head, key, specular
uniform float uShininess;
uniform float uOpacity;
out vec4 oColor;

void main() {
  // Behind the opaque scene: hidden (reversed Z, larger is nearer).
  if (gl_FragCoord.z < texelFetch(uSceneDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
  vec3 n = facingNormalVC();
  vec3 v = uOrtho == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-fin.posVC);
  vec3 l = normalize(uKeyDirVC);
  float head = max(dot(n, v), 0.0), key = max(dot(n, l), 0.0);
  float spec = uLightMix.w * (uLightMix.y * pow(head, uShininess) +
                              uLightMix.z * pow(max(dot(n, normalize(l + v)), 0.0), uShininess));
  vec3 c = uColor * (uLightMix.x + uLightMix.y * head + uLightMix.z * key) + spec;
  // More opaque where the surface turns away (a Fresnel-like rim), so that
  // the part's outline reads while its face stays clear.
  float alpha = min(1.0, uOpacity * (1.0 + 2.0 * pow(1.0 - head, 3.0)));
  oColor = vec4(c, alpha);
}
#else
uniform int uId;  // the id's bits
layout(location = 0) out vec4 oAlbedo;
layout(location = 1) out vec4 oNormalWC;
layout(location = 2) out uint oId;

void main() {
  oAlbedo = vec4(uColor, 1.0);
  oNormalWC = vec4(normalize(transpose(mat3(uViewWCVC)) * facingNormalVC()), 0.0);
  oId = uint(uId);
}
#endif
