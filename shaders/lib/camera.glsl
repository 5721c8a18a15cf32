// Per-frame camera uniforms (see tg::render::Camera). Depth is reversed:
// window depth 1 at the near plane, 0 at infinity (perspective) or far (ortho).
uniform mat4 uViewWCVC;
uniform mat4 uProjVCCC;
uniform vec2 uViewportDC;   // width, height in pixels
uniform int uOrtho;         // 0: perspective, 1: orthographic
uniform vec2 uRayScaleVC;   // perspective: tan(fov/2)*(aspect, 1); ortho: half extent (w, h)
uniform float uNearVC;
uniform float uFarVC;

// The ray through window position fragDC, with a unit component along -z_VC,
// so that its parameter is the depth along the view axis.
void rayThroughFragment(vec2 fragDC, out vec3 originVC, out vec3 dirVC) {
  vec2 ndc = fragDC / uViewportDC * 2.0 - 1.0;
  if (uOrtho == 1) {
    originVC = vec3(ndc * uRayScaleVC, 0.0);
    dirVC = vec3(0.0, 0.0, -1.0);
  } else {
    originVC = vec3(0.0);
    dirVC = vec3(ndc * uRayScaleVC, -1.0);
  }
}

float windowDepthFromViewDepth(float d) {
  return uOrtho == 1 ? (uFarVC - d) / (uFarVC - uNearVC) : uNearVC / d;
}

float viewDepthFromWindowDepth(float z) {
  return uOrtho == 1 ? uFarVC - z * (uFarVC - uNearVC) : uNearVC / z;
}
