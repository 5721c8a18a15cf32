#pragma once
// The camera uniforms of shaders/lib/camera.glsl, for every program that
// includes it: the glyph passes and the deferred ones, and the CPU glyph
// path's copy of the same maths (render/glsl_cpp.h).
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "gl/program.h"
#include "view/camera.h"

namespace tg::render {

struct CameraUniforms {
  glm::mat4 viewWCVC, projVCCC;
  glm::vec2 viewportDC, rayScaleVC;
  glm::vec2 pixelOffsetDC;  // GL's window axes: y up
  int ortho;
  float nearVC, farVC;
};

CameraUniforms cameraUniforms(const Camera& cam);
void setCameraUniforms(const gl::Program& prog, const Camera& cam);

}  // namespace tg::render
