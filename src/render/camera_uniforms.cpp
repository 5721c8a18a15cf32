#include "render/camera_uniforms.h"

#include <cmath>
#include <limits>

#include <glm/trigonometric.hpp>

namespace tg::render {

CameraUniforms cameraUniforms(const Camera& cam) {
  CameraUniforms u;
  u.viewWCVC = glm::mat4(cam.viewWCVC);
  u.projVCCC = glm::mat4(cam.projVCCC);
  u.viewportDC = glm::vec2(float(cam.width), float(cam.height));
  const bool ortho = cam.desc.projection == Projection::Orthographic;
  u.ortho = ortho ? 1 : 0;
  const double aspect = double(cam.width) / cam.height;
  const double h = ortho ? 0.5 * cam.desc.orthoHeight : std::tan(glm::radians(cam.desc.fovYDeg) * 0.5);
  u.rayScaleVC = glm::vec2(float(h * aspect), float(h));
  u.pixelOffsetDC = glm::vec2(float(cam.pixelOffsetDC.x), float(-cam.pixelOffsetDC.y));
  u.nearVC = float(cam.nearVC);
  u.farVC = ortho ? float(cam.farVC) : std::numeric_limits<float>::max();
  return u;
}

void setCameraUniforms(const gl::Program& prog, const Camera& cam) {
  const CameraUniforms u = cameraUniforms(cam);
  prog.set("uViewWCVC", u.viewWCVC);
  prog.set("uProjVCCC", u.projVCCC);
  prog.set("uViewportDC", u.viewportDC);
  prog.set("uOrtho", u.ortho);
  prog.set("uRayScaleVC", u.rayScaleVC);
  prog.set("uPixelOffsetDC", u.pixelOffsetDC);
  prog.set("uNearVC", u.nearVC);
  prog.set("uFarVC", u.farVC);
}

}  // namespace tg::render
