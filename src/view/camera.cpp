#include "view/camera.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace tg::render {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

const char* validateCamera(const CameraDesc& d) {
  if (!finite(d.eyeWC) || !finite(d.lookAtWC) || !finite(d.upWC)) return "camera vectors must be finite";
  const glm::dvec3 v = d.lookAtWC - d.eyeWC;
  if (glm::length(v) == 0.0) return "--eye and --look-at must differ";
  // Beyond this the view direction's length overflows, and every test below
  // would fail for that reason instead of its own.
  if (!std::isfinite(glm::length(v)) || !std::isfinite(glm::length(d.upWC)))
    return "camera vectors are too large (their lengths overflow a double)";
  if (glm::length(d.upWC) == 0.0) return "--up must be non-zero";
  if (glm::length(glm::cross(glm::normalize(v), glm::normalize(d.upWC))) < 1e-9)
    return "--up must not be parallel to the view direction";
  if (d.projection == Projection::Perspective && !(d.fovYDeg > 0.0 && d.fovYDeg < 180.0))
    return "--fov must be in (0, 180) degrees";
  if (d.projection == Projection::Orthographic && !(d.orthoHeight > 0.0 && std::isfinite(d.orthoHeight)))
    return "--ortho height must be positive and finite";
  return "";
}

double smallestResolvedView(const CameraDesc& d, int height) {
  const glm::dvec3 e = glm::abs(d.eyeWC), l = glm::abs(d.lookAtWC);
  const double distance = glm::length(d.lookAtWC - d.eyeWC);
  const double reach = std::max({e.x, e.y, e.z, l.x, l.y, l.z, distance});
  const double pixel = 2.0 * double(FLT_EPSILON) * reach;  // the smallest pixel, in world units
  if (d.projection == Projection::Orthographic) return pixel * height;
  return 2.0 * glm::degrees(std::atan(0.5 * pixel * height / distance));
}

Camera makeCamera(const CameraDesc& d, int width, int height, const glm::dvec3& lo, const glm::dvec3& hi) {
  Camera c;
  c.desc = d;
  c.width = width;
  c.height = height;
  c.viewWCVC = glm::lookAt(d.eyeWC, d.lookAtWC, d.upWC);
  // Depth range of the scene box along the view axis.
  double zmin = INFINITY, zmax = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 p((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
    const double z = -(c.viewWCVC * glm::dvec4(p, 1.0)).z;
    zmin = std::min(zmin, z);
    zmax = std::max(zmax, z);
  }
  const double span = std::max(zmax - zmin, 1e-30 + std::abs(zmax) * 1e-12);
  const double aspect = double(width) / double(height);
  if (d.projection == Projection::Perspective) {
    // Near as far out as the scene allows; when the eye is inside the box, a
    // small fraction of its depth, so only geometry within it is clipped.
    c.nearVC = std::max(zmin, 1e-6 * std::max(zmax, span));
    c.farVC = INFINITY;
    const double f = 1.0 / std::tan(glm::radians(d.fovYDeg) * 0.5);
    glm::dmat4 p(0.0);
    p[0][0] = f / aspect;
    p[1][1] = f;
    p[3][2] = c.nearVC;  // clip z = near, clip w = -z_VC: window depth = near / distance
    p[2][3] = -1.0;
    c.projVCCC = p;
  } else {
    c.nearVC = zmin - 0.01 * span;
    c.farVC = zmax + 0.01 * span;
    const double h = d.orthoHeight * 0.5, w = h * aspect;
    glm::dmat4 p(1.0);
    p[0][0] = 1.0 / w;
    p[1][1] = 1.0 / h;
    // z_VC = -near -> 1, z_VC = -far -> 0
    p[2][2] = 1.0 / (c.farVC - c.nearVC);
    p[3][2] = c.farVC / (c.farVC - c.nearVC);
    c.projVCCC = p;
  }
  return c;
}

RayWC Camera::rayThroughPixel(double px, double py) const { return rayThroughPixel(px, py, glm::inverse(viewWCVC)); }

RayWC Camera::rayThroughPixel(double px, double py, const glm::dmat4& wcFromVC) const {
  px += pixelOffsetDC.x;
  py += pixelOffsetDC.y;
  const double aspect = double(width) / double(height);
  const double xn = 2.0 * px / width - 1.0;
  const double yn = 1.0 - 2.0 * py / height;
  glm::dvec3 oVC(0.0), dVC(0, 0, -1);
  if (desc.projection == Projection::Perspective) {
    const double t = std::tan(glm::radians(desc.fovYDeg) * 0.5);
    dVC = glm::dvec3(xn * t * aspect, yn * t, -1.0);
  } else {
    oVC = glm::dvec3(xn * desc.orthoHeight * 0.5 * aspect, yn * desc.orthoHeight * 0.5, 0.0);
  }
  return {glm::dvec3(wcFromVC * glm::dvec4(oVC, 1.0)), glm::dvec3(wcFromVC * glm::dvec4(dVC, 0.0))};
}

Camera withPixelOffset(const Camera& cam, const glm::dvec2& offsetDC) {
  Camera c = cam;
  c.pixelOffsetDC = cam.pixelOffsetDC + offsetDC;
  // NDC x grows right, y up; rows grow down.
  glm::dmat4 shift(1.0);
  shift[3][0] = -2.0 * offsetDC.x / cam.width;
  shift[3][1] = 2.0 * offsetDC.y / cam.height;
  c.projVCCC = shift * cam.projVCCC;
  return c;
}

double Camera::windowDepthFromViewDepth(double dist) const {
  if (desc.projection == Projection::Perspective) return nearVC / dist;
  return (farVC - dist) / (farVC - nearVC);
}

double Camera::viewDepthFromWindowDepth(double z) const {
  if (desc.projection == Projection::Perspective) return z > 0.0 ? nearVC / z : INFINITY;
  return farVC - z * (farVC - nearVC);
}

glm::dvec3 Camera::viewDirectionWC() const { return glm::normalize(desc.lookAtWC - desc.eyeWC); }

CameraDesc frameBox(const glm::dvec3& lo, const glm::dvec3& hi, Projection p, double fovYDeg, double aspect,
                    const glm::dvec3& towardEyeWC, const glm::dvec3& upWC) {
  CameraDesc d;
  d.projection = p;
  d.fovYDeg = fovYDeg;
  const glm::dvec3 centre = 0.5 * (lo + hi);
  double r = 0.5 * glm::length(hi - lo);
  if (!(r > 0.0)) r = std::max(1.0, std::abs(centre.x) + std::abs(centre.y) + std::abs(centre.z)) * 1e-3;
  const double halfFov = glm::radians(fovYDeg) * 0.5;
  const double fit = std::min(std::tan(halfFov), std::tan(halfFov) * aspect);
  const double dist = r * std::sqrt(1.0 + 1.0 / (fit * fit));  // sphere tangent to the narrower frustum side
  d.lookAtWC = centre;
  d.eyeWC = centre + dist * towardEyeWC;
  d.upWC = upWC;
  d.orthoHeight = 2.0 * r * std::max(1.0, 1.0 / aspect) * 1.05;
  return d;
}

CameraDesc fitBox(const glm::dvec3& lo, const glm::dvec3& hi, Projection p, double fovYDeg, double aspect,
                  const glm::dvec3& towardEyeWC, const glm::dvec3& upWC) {
  CameraDesc d = frameBox(lo, hi, p, fovYDeg, aspect, towardEyeWC, upWC);
  // The box's half extents across the view (right, up) and along it: the
  // sums over its half edges, which for the default axes are its x, y, z.
  const glm::dvec3 half = 0.5 * (hi - lo);
  const glm::dvec3 right = glm::cross(upWC, towardEyeWC);
  auto across = [&](const glm::dvec3& a) {
    return std::abs(half.x * a.x) + std::abs(half.y * a.y) + std::abs(half.z * a.z);
  };
  const double halfRight = across(right), halfUp = across(upWC), halfDepth = across(towardEyeWC);
  if (!(halfRight > 0.0 || halfUp > 0.0)) return d;  // a point or a line along the view: the sphere's view
  constexpr double kMargin = 1.05;
  const double tanY = std::tan(glm::radians(fovYDeg) * 0.5), tanX = tanY * aspect;
  // The near face's corners bound the view: they are the closest to the eye.
  const double dist = halfDepth + kMargin * std::max(halfRight / tanX, halfUp / tanY);
  d.eyeWC = d.lookAtWC + dist * towardEyeWC;
  d.orthoHeight = 2.0 * kMargin * std::max(halfUp, halfRight / aspect);
  return d;
}

}  // namespace tg::render
