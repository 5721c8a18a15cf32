#version 450 core
// Screen-space ambient occlusion (render/ao_pass.h): the fraction of a
// normal-oriented hemisphere of radius uRadiusVC that the depth buffer
// leaves open, before the blur.
#include "lib/bindings.h"
#include "lib/camera.glsl"
#include "lib/view_position.glsl"

layout(binding = TG_UNIT_EFFECT_DEPTH) uniform sampler2D uDepth;  // reversed window depth
layout(binding = TG_UNIT_NORMAL) uniform sampler2D uNormalWC;
layout(binding = TG_UNIT_ID) uniform usampler2D uId;

uniform float uRadiusVC;
uniform float uStrength;
uniform int uSamples;

out float oAo;

const uint kNoGlyph = 0xFFFFFFFFu;
const float kGoldenAngle = 2.39996323;

// A 4 x 4 ordered (Bayer) pattern: the blur's 4 x 4 window sees each of the
// 16 kernel rotations once, so the noise averages out exactly on flat areas.
float bayer4(ivec2 p) {
  const float m[16] = float[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
  return m[(p.y & 3) * 4 + (p.x & 3)] / 16.0;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  oAo = 1.0;
  if (texelFetch(uId, p, 0).r == kNoGlyph) return;
  vec3 posVC = positionVC(gl_FragCoord.xy, texelFetch(uDepth, p, 0).r);
  vec3 n = normalize(mat3(uViewWCVC) * texelFetch(uNormalWC, p, 0).xyz);
  vec3 originVC, dirVC;
  rayThroughFragment(gl_FragCoord.xy, originVC, dirVC);
  if (dot(n, dirVC) > 0.0) n = -n;  // towards the eye, as lighting.frag
  // A tangent frame turned by this pixel's rotation.
  vec3 helper = abs(n.z) < 0.9 ? vec3(0, 0, 1) : vec3(1, 0, 0);
  vec3 t = normalize(cross(helper, n));
  vec3 b = cross(n, t);
  float turn = 6.28318531 * bayer4(p);
  // Depth tolerance. A sample is compared with the depth at its pixel's
  // centre, not at its own position: on a surface tilted away from the eye
  // that depth runs ahead by up to a pixel's footprint times the slope, and
  // without that allowance a lone convex glyph would darken its own rim.
  float footprint = 2.0 * uRayScaleVC.y / uViewportDC.y * (uOrtho == 1 ? 1.0 : -posVC.z);
  float slope = sqrt(max(0.0, 1.0 - n.z * n.z)) / max(abs(n.z), 0.02);
  float bias = 0.03 * uRadiusVC + 1.5 * footprint * slope;
  float open = 0.0, occluded = 0.0;
  for (int i = 0; i < uSamples; ++i) {
    // Cosine-weighted directions on a Fibonacci spiral; distances spread
    // over (0.1, 1] radius, denser near the point, where contact darkens.
    float u = (float(i) + 0.5) / float(uSamples);
    float r = sqrt(u), phi = float(i) * kGoldenAngle + turn;
    vec3 dirGC = vec3(r * cos(phi), r * sin(phi), sqrt(1.0 - u));
    float len = fract(float(i) * 0.618034 + 0.5);
    len = mix(0.1, 1.0, len * len);
    vec3 sVC = posVC + uRadiusVC * len * (dirGC.x * t + dirGC.y * b + dirGC.z * n);
    if (sVC.z >= -uNearVC) continue;  // behind the near plane: no depth to compare
    ivec2 q = ivec2(windowFromVC(sVC));
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(uViewportDC)))) continue;
    open += 1.0;
    float zq = texelFetch(uDepth, q, 0).r;
    if (zq <= 0.0) continue;  // background
    float sceneDepth = viewDepthFromWindowDepth(zq);
    float sampleDepth = -sVC.z;
    if (sceneDepth < sampleDepth - bias) {
      // Occluders far in front of the point (a glyph nearer the eye) count
      // less: a range check, fading over one radius.
      float gap = -posVC.z - sceneDepth;
      occluded += clamp(2.0 - gap / uRadiusVC, 0.0, 1.0);
    }
  }
  if (open > 0.0) oAo = clamp(1.0 - uStrength * occluded / open, 0.0, 1.0);
}
