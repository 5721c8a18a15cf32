// Per-frame camera uniforms (see tg::render::Camera). Depth is reversed:
// window depth 1 at the near plane, 0 at infinity (perspective) or far (ortho).
// In the GLSL/C++ subset (lib/glsl_cpp.h).
// C++ includes it as shaders/lib/glsl_cpp.h first (render/glsl_cpp.h).
#ifndef TG_GLSL_CPP_H
#include "lib/glsl_cpp.h"
#endif
uniform mat4 uViewWCVC;
uniform mat4 uProjVCCC;
uniform vec2 uViewportDC;   // width, height in pixels
uniform int uOrtho;         // 0: perspective, 1: orthographic
uniform vec2 uRayScaleVC;   // perspective: tan(fov/2)*(aspect, 1); ortho: half extent (w, h)
uniform float uNearVC;
uniform float uFarVC;
uniform vec2 uPixelOffsetDC;  // anti-aliasing's sub-pixel jitter, GL's window axes; zero otherwise

// The ray through window position fragDC, with a unit component along -z_VC,
// so that its parameter is the depth along the view axis.
void rayThroughFragment(vec2 fragDC, TG_OUT(vec3) originVC, TG_OUT(vec3) dirVC) {
  vec2 ndc = (fragDC + uPixelOffsetDC) / uViewportDC * 2.0f - 1.0f;
  if (uOrtho == 1) {
    originVC = vec3(ndc * uRayScaleVC, 0.0f);
    dirVC = vec3(0.0f, 0.0f, -1.0f);
  } else {
    originVC = vec3(0.0f);
    dirVC = vec3(ndc * uRayScaleVC, -1.0f);
  }
}

float windowDepthFromViewDepth(float d) {
  return uOrtho == 1 ? (uFarVC - d) / (uFarVC - uNearVC) : uNearVC / d;
}

float viewDepthFromWindowDepth(float z) {
  return uOrtho == 1 ? uFarVC - z * (uFarVC - uNearVC) : uNearVC / z;
}
