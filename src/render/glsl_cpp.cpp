#include "render/glsl_cpp.h"

#include "render/camera_uniforms.h"

namespace tg::render::glsl {

void Shaders::setCamera(const Camera& cam) {
  const CameraUniforms u = cameraUniforms(cam);
  uViewWCVC = u.viewWCVC;
  uProjVCCC = u.projVCCC;
  uViewportDC = u.viewportDC;
  uOrtho = u.ortho;
  uRayScaleVC = u.rayScaleVC;
  uPixelOffsetDC = u.pixelOffsetDC;
  uNearVC = u.nearVC;
  uFarVC = u.farVC;
}

// As setGlyphUniforms (render/kind_programs.cpp) converts them.
void Shaders::setGlyph(const FrameParams& p) {
  uScale = float(p.scale);
  uMagnitude = int(p.sizing.magnitude);
  uLambda0 = float(p.sizing.lambda0);
  uMaxRadiusWC = float(p.sizing.maxRadiusWC);
  uFaMin = float(p.faMin);
  uSlabAxis = p.slab.axis;
  uSlabNormal = vec3(p.slab.direction());
  uSlabWC = vec2(float(p.slab.lo), float(p.slab.hi));
  uBlobBlobbiness = float(p.blob.blobbiness);
  uBlobThreshold = float(p.blob.threshold);
  uBlobCutoff = float(p.blob.cutoff);
}

}  // namespace tg::render::glsl
