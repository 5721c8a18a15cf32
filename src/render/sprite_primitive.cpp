#include "render/sprite_primitive.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec4.hpp>

namespace tg::render {
namespace {

// The widest margin a sprite program adds to its rectangle: one pixel on
// each side (prism.vert; the ray casters add a quarter).
constexpr double kMarginPx = 2.0;

}  // namespace

// Each glyph lies in the view-aligned cube of half-side r about its centre c
// (VC). With Z = -z_VC >= Zn > 0 over the cube and NDC x = sx X / Z, the
// cube's NDC width is max X/Z - min X/Z over its corners: 2 r sx / Zn when it
// straddles X = 0, else (2 r sx / Zn)(1 + b / Zf) with b = |c.x| - r > 0; a
// rectangle that survives clamping to [-1, 1] has sx b / Zf < 1, so the
// clamped width is below 2 r (sx + 1) / Zn either way. Orthographic: 2 r sx.
double spriteSizeBoundPx(const Camera& cam, const glm::dvec3& centresLoWC, const glm::dvec3& centresHiWC,
                         double radiusWC) {
  const double inf = std::numeric_limits<double>::infinity();
  const glm::dmat4& p = cam.projVCCC;
  if (!(radiusWC >= 0.0) || p[2][0] != 0.0 || p[2][1] != 0.0) return inf;
  // Float rounding of the shaders' rectangles, far below a pixel.
  const double r = radiusWC * (1.0 + 1e-4);
  const double sx = std::abs(p[0][0]), sy = std::abs(p[1][1]);
  const bool ortho = cam.desc.projection == Projection::Orthographic;
  double scale = 2.0 * r;  // NDC extent per unit of sx or sy
  if (!ortho) {
    double zc = inf;
    for (int k = 0; k < 8; ++k) {
      const glm::dvec3 cWC((k & 1) ? centresHiWC.x : centresLoWC.x, (k & 2) ? centresHiWC.y : centresLoWC.y,
                           (k & 4) ? centresHiWC.z : centresLoWC.z);
      zc = std::min(zc, -(cam.viewWCVC * glm::dvec4(cWC, 1.0)).z);
    }
    const double zn = zc - r;
    // Within a tenth of a radius of the eye plane the bound is useless anyway.
    if (!(zn > 0.1 * r) || !std::isfinite(zn)) return inf;
    scale /= zn;
  }
  const double wNdc = scale * (ortho ? sx : sx + 1.0), hNdc = scale * (ortho ? sy : sy + 1.0);
  const double bound = std::max(0.5 * cam.width * std::min(wNdc, 2.0), 0.5 * cam.height * std::min(hNdc, 2.0));
  return bound + kMarginPx;
}

bool pointSpritesFit(const Camera& cam, const glm::dvec3& centresLoWC, const glm::dvec3& centresHiWC,
                     double radiusWC, double maxPointPx) {
  return spriteSizeBoundPx(cam, centresLoWC, centresHiWC, radiusWC) <= maxPointPx;
}

double typicalSpritePx(const Camera& cam, const glm::dvec3& centresLoWC, const glm::dvec3& centresHiWC,
                       double diameterWC) {
  const double focalPx = 0.5 * cam.height * std::abs(cam.projVCCC[1][1]);
  if (cam.desc.projection == Projection::Orthographic) return diameterWC * focalPx;
  const double depthVC = -(cam.viewWCVC * glm::dvec4(0.5 * (centresLoWC + centresHiWC), 1.0)).z;
  if (!(depthVC > 0.0)) return std::numeric_limits<double>::infinity();
  return diameterWC * focalPx / depthVC;
}

}  // namespace tg::render
