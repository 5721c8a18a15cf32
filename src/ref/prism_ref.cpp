#include "ref/prism_ref.h"

#include <algorithm>
#include <cmath>

#include "ref/pixel_loop.h"

namespace tg::ref {
namespace {

// Teem's tenAniso_Cl1 and _Cp1: the trace clamped at 0 below.
double cl1(const glm::dvec3& l) {
  const double sum = std::max(0.0, l[0] + l[1] + l[2]);
  return sum > 0.0 ? (l[0] - l[1]) / sum : 0.0;
}
double cp1(const glm::dvec3& l) {
  const double sum = std::max(0.0, l[0] + l[1] + l[2]);
  return sum > 0.0 ? 2.0 * (l[1] - l[2]) / sum : 0.0;
}

// The interval of t where lo <= o + t d <= hi along one axis.
bool slab(double o, double d, double& t0, double& t1, int k, int& kIn, int& kOut) {
  if (d == 0.0) return std::abs(o) <= 1.0;
  const double a = (-1.0 - o) / d, b = (1.0 - o) / d;
  if (std::min(a, b) > t0) t0 = std::min(a, b), kIn = k;
  if (std::max(a, b) < t1) t1 = std::max(a, b), kOut = k;
  return true;
}

RefImage render(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs, const RefParams& p,
                bool cylinder) {
  std::vector<detail::Prepared> prep;
  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    detail::Prepared q;
    if (!detail::prepareGlyph(glyphs[i], p, i, q)) continue;
    q.radius = glm::length(q.axes);  // the box's half diagonal holds both solids
    if (cylinder) {
      const auto& l = glyphs[i].eigenvalues;
      const int ax = teemCylinderAxis(glm::dvec3(l[0], l[1], l[2]));
      // GC z on the cylinder's axis: a cyclic permutation keeps the frame right-handed.
      const glm::dvec3 axes = q.axes;
      const glm::dvec3 frame[3] = {q.frame[0], q.frame[1], q.frame[2]};
      for (int k = 0; k < 3; ++k) {
        q.frame[k] = frame[(ax + 1 + k) % 3];
        q.axes[k] = axes[(ax + 1 + k) % 3];
      }
    }
    prep.push_back(q);
  }
  return detail::castRays(cam, prep,
                          [&](const detail::Prepared&, const glm::dvec3& o, const glm::dvec3& d, double tNear,
                              double tBest, double& t, glm::dvec3& nGC) {
                            const bool hit = cylinder ? cylinderFirstHit(o, d, tNear, t, nGC)
                                                      : boxFirstHit(o, d, tNear, t, nGC);
                            return hit && t < tBest;
                          });
}

}  // namespace

int teemCylinderAxis(const glm::dvec3& l) {
  if (l[2] > 0.0) return std::min(0.99, cl1(l)) > std::min(0.99, cp1(l)) ? 0 : 2;
  if (l[0] < 0.0) {
    const glm::dvec3 a(-l[2], -l[1], -l[0]);
    return std::min(0.99, cl1(a)) > std::min(0.99, cp1(a)) ? 2 : 0;
  }
  if (l[1] >= -l[2]) return 2;                 // zone B-F-C
  if (l[0] >= -l[2]) return l[1] >= 0.0 ? 2 : 0;  // B-E-F, B-D-E
  if (l[0] < -l[1]) return 0;                  // D-G-H
  return l[1] < 0.0 ? 0 : 2;                   // E-D-H, F-E-H
}

bool cylinderFirstHit(const glm::dvec3& o, const glm::dvec3& d, double tNear, double& t, glm::dvec3& nGC) {
  // The side: |o.xy + t d.xy|^2 <= 1, from the closest approach to the axis.
  double s0 = -INFINITY, s1 = INFINITY;
  const double dd = d.x * d.x + d.y * d.y;
  if (dd > 0.0) {
    const double tm = -(o.x * d.x + o.y * d.y) / dd;
    const double qx = o.x + tm * d.x, qy = o.y + tm * d.y;
    const double h = 1.0 - (qx * qx + qy * qy);
    if (h < 0.0) return false;
    const double s = std::sqrt(h / dd);
    s0 = tm - s;
    s1 = tm + s;
  } else if (o.x * o.x + o.y * o.y > 1.0) {
    return false;
  }
  double c0 = -INFINITY, c1 = INFINITY;
  int kIn = -1, kOut = -1;
  if (!slab(o.z, d.z, c0, c1, 2, kIn, kOut)) return false;
  const double t0 = std::max(s0, c0), t1 = std::min(s1, c1);
  if (!(t0 <= t1)) return false;
  const bool entry = t0 >= tNear;
  t = entry ? t0 : t1;
  if (!(t >= tNear)) return false;
  const glm::dvec3 pt = o + t * d;
  const bool cap = entry ? c0 > s0 : c1 < s1;
  nGC = cap ? glm::dvec3(0.0, 0.0, pt.z > 0.0 ? 1.0 : -1.0) : glm::dvec3(pt.x, pt.y, 0.0);
  return true;
}

bool boxFirstHit(const glm::dvec3& o, const glm::dvec3& d, double tNear, double& t, glm::dvec3& nGC) {
  double t0 = -INFINITY, t1 = INFINITY;
  int kIn = -1, kOut = -1;
  for (int k = 0; k < 3; ++k)
    if (!slab(o[k], d[k], t0, t1, k, kIn, kOut)) return false;
  if (!(t0 <= t1)) return false;
  const bool entry = t0 >= tNear;
  t = entry ? t0 : t1;
  if (!(t >= tNear)) return false;
  const int k = entry ? kIn : kOut;
  nGC = glm::dvec3(0.0);
  nGC[k] = (entry ? -1.0 : 1.0) * (d[k] > 0.0 ? 1.0 : -1.0);
  return true;
}

RefImage renderCylinders(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs, const RefParams& p) {
  return render(cam, glyphs, p, true);
}

RefImage renderBoxes(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs, const RefParams& p) {
  return render(cam, glyphs, p, false);
}

}  // namespace tg::ref
