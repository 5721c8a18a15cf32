#include "view/frustum.h"

#include <cmath>

#include <glm/mat4x4.hpp>

namespace tg::render {

FrustumWC frustumPlanesWC(const Camera& cam) {
  const glm::dmat4 m = cam.projVCCC * cam.viewWCVC;
  auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
  const glm::dvec4 x = row(0), y = row(1), z = row(2), w = row(3);
  return {w + x, w - x, w + y, w - y, z, w - z};
}

namespace {

// The signed distance (times |n|) of the box corner farthest along, or
// against, the plane normal.
double extreme(const glm::dvec4& p, const glm::dvec3& lo, const glm::dvec3& hi, bool towards) {
  const glm::dvec3 c = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
  const double r = std::abs(p.x) * h.x + std::abs(p.y) * h.y + std::abs(p.z) * h.z;
  const double d = p.x * c.x + p.y * c.y + p.z * c.z + p.w;
  return towards ? d + r : d - r;
}

}  // namespace

bool boxOutside(const FrustumWC& f, const glm::dvec3& lo, const glm::dvec3& hi) {
  for (const glm::dvec4& p : f)
    if (extreme(p, lo, hi, true) < 0.0) return true;
  return false;
}

bool boxInside(const FrustumWC& f, const glm::dvec3& lo, const glm::dvec3& hi) {
  for (const glm::dvec4& p : f)
    if (!(extreme(p, lo, hi, false) >= 0.0)) return false;
  return true;
}

}  // namespace tg::render
