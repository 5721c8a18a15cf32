#include "app/orbit_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace tg::app {
namespace {

glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double deg) {
  return glm::dvec3(glm::rotate(glm::dmat4(1.0), glm::radians(deg), axis) * glm::dvec4(v, 0.0));
}

}  // namespace

void OrbitCamera::orbit(double yawDeg, double pitchDeg) {
  const glm::dvec3 up = glm::normalize(d_.upWC);
  glm::dvec3 offset = rotate(d_.eyeWC - d_.lookAtWC, up, -yawDeg);
  // Angle from the up axis, kept within [1, 179] degrees.
  const double r = glm::length(offset);
  const double polar = glm::degrees(std::acos(std::clamp(glm::dot(offset, up) / r, -1.0, 1.0)));
  const double target = std::clamp(polar - pitchDeg, 1.0, 179.0);
  const glm::dvec3 right = glm::normalize(glm::cross(up, offset));
  offset = rotate(offset, right, target - polar);
  d_.eyeWC = d_.lookAtWC + offset;
}

void OrbitCamera::pan(double dx, double dy) {
  const glm::dvec3 view = d_.lookAtWC - d_.eyeWC;
  const glm::dvec3 right = glm::normalize(glm::cross(view, d_.upWC));
  const glm::dvec3 up = glm::normalize(glm::cross(right, view));
  const double height = d_.projection == render::Projection::Orthographic
                            ? d_.orthoHeight
                            : 2.0 * glm::length(view) * std::tan(glm::radians(d_.fovYDeg) * 0.5);
  const glm::dvec3 shift = height * (dx * right + dy * up);
  d_.eyeWC -= shift;
  d_.lookAtWC -= shift;
}

void OrbitCamera::zoom(double factor) {
  if (!(factor > 0.0)) return;
  if (d_.projection == render::Projection::Orthographic) d_.orthoHeight /= factor;
  else d_.eyeWC = d_.lookAtWC + (d_.eyeWC - d_.lookAtWC) / factor;
}

}  // namespace tg::app
