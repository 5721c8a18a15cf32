// Soft shadows of the key light (tg::render::ShadowPass): percentage closer
// filtering (Reeves et al. 1987) of the light-space depth map over the
// penumbra width, 16 bilinear taps (64 texels, as Sigg et al. 2006 §5); the 4
// corner taps go first, and where they agree the pixel is wholly lit or
// wholly shadowed and the other 12 are skipped (Sigg et al. test 8 samples
// before their 64). Requires lib/camera.glsl.
#include "lib/bindings.h"
#pragma tg option TG_SHADOWS
#ifdef TG_SHADOWS
layout(binding = TG_UNIT_SHADOW_SCENE_DEPTH) uniform sampler2D uSceneDepth;  // the G-buffer's window depth
layout(binding = TG_UNIT_SHADOW_MAP) uniform sampler2D uShadowMap;   // window depth along the light, reversed; 0: empty
uniform mat4 uLightFromVC;       // camera VC -> the light camera's VC (rigid)
uniform float uLightHalfExtent;  // half the map's side, world units
uniform vec2 uLightNearFar;      // the light camera's depth range
uniform float uShadowMapSize;    // texels per side
uniform float uShadowKernel;     // penumbra width, texels
uniform float uShadowBias;       // world units along the light
uniform float uShadowNormalOffset;  // world units along the normal
uniform int uShadowReceiverPlane;
uniform float uShadowStrength;

// The receiver plane's slope is capped where the light grazes it (cosine
// below this), where the key light is at most 5% of its peak anyway.
const float kMinShadowCos = 0.05;

// The four texels around position t (texel units), one gather, each lit
// (1) where its surface is not in front of the receiver: whose depth there
// is dP plus its plane's rise from q to the texel's centre. Bilinearly
// weighted. The map clamps to its edge, which the light camera's margin
// leaves empty (window depth 0: nothing, lit).
float shadowTap(vec2 t, float dP, vec2 slope, vec2 q) {
  vec2 b = floor(t - 0.5);
  vec2 f = t - 0.5 - b;
  // Gather order: (0, 1), (1, 1), (1, 0), (0, 0) from texel b.
  vec4 w = textureGather(uShadowMap, (b + 1.0) / uShadowMapSize);
  vec4 dMap = uLightNearFar.y - w * (uLightNearFar.y - uLightNearFar.x);
  vec2 c = b + 0.5 - q;  // texel (0, 0)'s centre from q
  vec4 rise = vec4(dot(slope, c + vec2(0, 1)), dot(slope, c + vec2(1, 1)), dot(slope, c + vec2(1, 0)), dot(slope, c));
  vec4 lit = vec4(greaterThanEqual(dMap, dP + rise - uShadowBias)) + vec4(lessThanEqual(w, vec4(0.0)));
  lit = min(lit, 1.0);
  return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
}

// Visibility of the key light, 0..1, at the surface point pVC with unit
// normal nVC (facing the key light).
float keyLightVisibility(vec3 pVC, vec3 nVC) {
  vec3 pL = (uLightFromVC * vec4(pVC + uShadowNormalOffset * nVC, 1.0)).xyz;
  vec3 nL = mat3(uLightFromVC) * nVC;
  float dP = -pL.z;
  vec2 q = (pL.xy / uLightHalfExtent * 0.5 + 0.5) * uShadowMapSize;
  // Depth rise of the tangent plane per texel along the map's axes.
  float texelWorld = 2.0 * uLightHalfExtent / uShadowMapSize;
  vec2 slope = uShadowReceiverPlane != 0 ? nL.xy / max(nL.z, kMinShadowCos) * texelWorld : vec2(0.0);
  // Tap k of 4 along an axis sits at the midpoint of the k-th quarter of the kernel.
  float h = uShadowKernel / 4.0;
  float corners = shadowTap(q + vec2(-1.5, -1.5) * h, dP, slope, q) + shadowTap(q + vec2(1.5, -1.5) * h, dP, slope, q) +
                  shadowTap(q + vec2(-1.5, 1.5) * h, dP, slope, q) + shadowTap(q + vec2(1.5, 1.5) * h, dP, slope, q);
  if (corners == 0.0 || corners == 4.0) return corners * 0.25;
  float sum = corners;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      if ((i == 1 || i == 2) || (j == 1 || j == 2)) sum += shadowTap(q + (vec2(i, j) - 1.5) * h, dP, slope, q);
  return sum / 16.0;
}
#endif
