#version 450 core
// Deferred Blinn-Phong: ambient, a head light at the eye and one key light,
// shadowed when compiled with TG_SHADOWS (lib/shadow.glsl).
#include "lib/bindings.h"
#include "lib/camera.glsl"
#include "lib/shadow.glsl"
#include "lib/aa_edge.glsl"

layout(binding = TG_UNIT_ALBEDO) uniform sampler2D uAlbedo;
layout(binding = TG_UNIT_NORMAL) uniform sampler2D uNormalWC;
layout(binding = TG_UNIT_ID) uniform usampler2D uId;

uniform vec4 uBackground;
uniform vec3 uKeyDirVC;    // towards the key light
uniform vec4 uLightMix;    // ambient, head, key, specular
uniform float uShininess;
// 1 for anti-aliasing's extra samples (render/antialias_pass.h): only the
// frame's silhouette pixels are kept, so only they are lit.
uniform int uEdgesOnly;

#pragma tg option TG_AO
#ifdef TG_AO
layout(binding = TG_UNIT_AO) uniform sampler2D uAo;
#endif

out vec4 oColor;

const uint kNoGlyph = 0xFFFFFFFFu;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (uEdgesOnly == 1 && !aaEdge(p)) discard;
  if (texelFetch(uId, p, 0).r == kNoGlyph) {
    oColor = uBackground;
    return;
  }
  vec3 albedo = texelFetch(uAlbedo, p, 0).rgb;
  vec3 n = normalize(mat3(uViewWCVC) * texelFetch(uNormalWC, p, 0).xyz);
  vec3 originVC, dirVC;
  rayThroughFragment(gl_FragCoord.xy, originVC, dirVC);
  vec3 v = normalize(-dirVC);
  if (dot(n, v) < 0.0) n = -n;  // the inside wall of a glyph the camera is in
  vec3 l = normalize(uKeyDirVC);
  float head = max(dot(n, v), 0.0);
  float key = max(dot(n, l), 0.0);
  float specHead = pow(head, uShininess);  // half vector of the head light is v
  float specKey = pow(max(dot(n, normalize(l + v)), 0.0), uShininess);
#ifdef TG_SHADOWS
  if (key > 0.0) {
    vec3 pVC = originVC + viewDepthFromWindowDepth(texelFetch(uSceneDepth, p, 0).r) * dirVC;
    float lit = mix(1.0, keyLightVisibility(pVC, n), uShadowStrength);
    key *= lit;
    specKey *= lit;
  }
#endif
  // The share of ambient and head light that reaches the point: ambient
  // occlusion dims both, as the head light is this renderer's fill light.
  float fill = 1.0;
#ifdef TG_AO
  fill = texelFetch(uAo, p, 0).r;
#endif
  vec3 c = albedo * (fill * (uLightMix.x + uLightMix.y * head) + uLightMix.z * key) +
           uLightMix.w * (uLightMix.y * specHead + uLightMix.z * specKey);
  oColor = vec4(c, 1.0);
}
