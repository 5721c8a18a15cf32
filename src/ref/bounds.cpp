#include <cmath>

#include <glm/mat4x4.hpp>

#include "ref/ellipsoid_ref.h"

namespace tg::ref {

RectNDC ellipsoidRectNDC(const render::Camera& cam, const tensor::GlyphRecord& g, double scale) {
  const glm::dvec3 a = tensor::ellipsoidAxes(g, scale);
  glm::dvec3 frame[3];
  tensor::frameAxes(g, frame);
  // T: parameter space -> WC (eq. 2), columns u v w c.
  glm::dmat4 t(0.0);
  for (int k = 0; k < 3; ++k) t[k] = glm::dvec4(frame[k] * a[k], 0.0);
  t[3] = glm::dvec4(g.posWC[0], g.posWC[1], g.posWC[2], 1.0);
  const glm::dmat4 pmt = cam.projVCCC * cam.viewWCVC * t;
  auto row = [&](int i) { return glm::dvec4(pmt[0][i], pmt[1][i], pmt[2][i], pmt[3][i]); };
  // The bilinear form with D = diag(1, 1, 1, -1).
  auto form = [](const glm::dvec4& u, const glm::dvec4& v) { return u.x * v.x + u.y * v.y + u.z * v.z - u.w * v.w; };
  const glm::dvec4 r1 = row(0), r2 = row(1), r4 = row(3);
  RectNDC rect;
  const double a4 = form(r4, r4);
  if (!(a4 < 0.0)) {
    rect.full = true;
    rect.xmin = rect.ymin = -1.0;
    rect.xmax = rect.ymax = 1.0;
    return rect;
  }
  auto solve = [&](const glm::dvec4& ri, double& lo, double& hi) {
    const double b = form(ri, r4), c = form(ri, ri);
    const double s = std::sqrt(std::max(b * b - a4 * c, 0.0));
    const double x0 = (b + s) / a4, x1 = (b - s) / a4;
    lo = std::min(x0, x1);
    hi = std::max(x0, x1);
  };
  solve(r1, rect.xmin, rect.xmax);
  solve(r2, rect.ymin, rect.ymax);
  return rect;
}

}  // namespace tg::ref
