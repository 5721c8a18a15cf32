#include "render/camera_uniforms.h"

#include <cmath>
#include <limits>

#include <glm/trigonometric.hpp>

namespace tg::render {

void setCameraUniforms(const gl::Program& prog, const Camera& cam) {
  prog.set("uViewWCVC", glm::mat4(cam.viewWCVC));
  prog.set("uProjVCCC", glm::mat4(cam.projVCCC));
  prog.set("uViewportDC", glm::vec2(float(cam.width), float(cam.height)));
  const bool ortho = cam.desc.projection == Projection::Orthographic;
  prog.set("uOrtho", ortho ? 1 : 0);
  const double aspect = double(cam.width) / cam.height;
  const double h = ortho ? 0.5 * cam.desc.orthoHeight : std::tan(glm::radians(cam.desc.fovYDeg) * 0.5);
  prog.set("uRayScaleVC", glm::vec2(float(h * aspect), float(h)));
  prog.set("uNearVC", float(cam.nearVC));
  prog.set("uFarVC", ortho ? float(cam.farVC) : std::numeric_limits<float>::max());
}

}  // namespace tg::render
