#include "tensor/superquadric.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace tg::tensor {
namespace {

// Westin's measures as Teem's tenAniso_Cl1 / tenAniso_Cp1 (trace-normalised),
// clamped at 0.99 as tenGlyphGen does.
void clcp1(const glm::dvec3& l, double& cl, double& cp) {
  const double tr = l.x + l.y + l.z;
  cl = std::min(0.99, (l.x - l.y) / tr);
  cp = std::min(0.99, 2.0 * (l.y - l.z) / tr);
}

SuperquadricShape kindlmann2004(const glm::dvec3& l, double gamma, bool mirrored) {
  double cl, cp;
  clcp1(l, cl, cp);
  SuperquadricShape s;
  if (cl > cp) {
    s.axis = mirrored ? 2 : 0;
    s.a = std::pow(1.0 - cp, gamma);
    s.b = std::pow(1.0 - cl, gamma);
  } else {
    s.axis = mirrored ? 0 : 2;
    s.a = std::pow(1.0 - cl, gamma);
    s.b = std::pow(1.0 - cp, gamma);
  }
  s.c = s.b;
  return s;
}

// Schultz & Kindlmann 2010 through Teem: the poles of the eigenvalue sphere
// and the (a, b, c) of the base shapes blended between them.
SuperquadricShape schultz2010(const glm::dvec3& l) {
  const double r2 = 1.0 / std::sqrt(2.0), r3 = 1.0 / std::sqrt(3.0);
  const glm::dvec3 B(1, 0, 0), C(r2, r2, 0), D(r3, -r3, -r3), E(r2, 0, -r2), F(r3, r3, -r3), G(0, -r2, -r2),
      H(0, 0, -1);
  const glm::dvec3 funk(0, 4, 2), thrn(1, 4, 4), octa(0, 2, 2), cone(1, 2, 2);
  const glm::dvec3 n = glm::normalize(l);
  glm::dvec3 q;
  int axis;
  auto blend = [&](const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& s0,
                   const glm::dvec3& s1, const glm::dvec3& s2, int ax) {
    const glm::dvec3 w = sphericalBarycentric(p0, p1, p2, n);
    q = w.x * s0 + w.y * s1 + w.z * s2;
    axis = ax;
  };
  if (l.y >= -l.z) blend(B, F, C, octa, thrn, cone, 2);
  else if (l.x >= -l.z) {
    if (l.y >= 0) blend(B, E, F, octa, funk, thrn, 2);
    else blend(B, D, E, cone, thrn, funk, 0);
  } else if (l.x < -l.y) blend(D, G, H, thrn, cone, octa, 0);
  else if (l.y < 0) blend(E, D, H, funk, thrn, octa, 0);
  else blend(F, E, H, thrn, funk, cone, 2);
  return {q.x, q.y, q.z, axis};
}

}  // namespace

double sphericalTriangleArea(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  // Van Oosterom & Strackee 1983: tan(E/2) = |a.(b x c)| / (1 + a.b + b.c + c.a).
  return 2.0 * std::atan2(std::abs(glm::dot(a, glm::cross(b, c))),
                          1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a));
}

glm::dvec3 sphericalBarycentric(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2,
                                const glm::dvec3& v) {
  const glm::dvec3 w(sphericalTriangleArea(v, p1, p2), sphericalTriangleArea(p0, v, p2),
                     sphericalTriangleArea(p0, p1, v));
  return w / (w.x + w.y + w.z);
}

SuperquadricShape superquadricShape(const glm::dvec3& l, double gamma) {
  SuperquadricShape s;
  if (l.x == 0.0 && l.z == 0.0) return s;  // the zero tensor: no glyph is drawn
  if (l.z > 0.0) s = kindlmann2004(l, gamma, false);
  else if (l.x < 0.0) s = kindlmann2004(glm::dvec3(-l.z, -l.y, -l.x), gamma, true);
  else s = schultz2010(l);
  s.a = std::max(s.a, kMinShapeExponent);
  s.b = std::max(s.b, kMinShapeExponent);
  s.c = std::max(s.c, kMinShapeExponent);
  return s;
}

bool isEllipsoid(const SuperquadricShape& s) { return s.a == 1.0 && s.b == 1.0 && s.c == 1.0; }

double superquadricGauge(const SuperquadricShape& s, const glm::dvec3& p, glm::dvec3* grad) {
  // Every power is taken of a ratio in [0, 1], so nothing overflows; 0^k
  // underflows to 0 harmlessly for the positive exponents used here.
  const double ax = std::abs(p.x), ay = std::abs(p.y), az = std::abs(p.z);
  const double m = std::max(ax, ay);
  double sxy = 0, rx = 0, ry = 0;  // s, and |x|^(2/a)/(|x|^(2/a)+|y|^(2/a)) over |x| (ditto y)
  if (m > 0) {
    const double px = std::pow(ax / m, 2.0 / s.a), py = std::pow(ay / m, 2.0 / s.a);
    sxy = m * std::pow(px + py, s.a / 2.0);
    rx = std::pow(ax / m, 2.0 / s.a - 1.0) / ((px + py) * m);
    ry = std::pow(ay / m, 2.0 / s.a - 1.0) / ((px + py) * m);
  }
  if (sxy == 0 && az == 0) {
    if (grad) *grad = glm::dvec3(0);
    return 0;
  }
  // u = s^(2/b), w = |z|^(2/c), in log2 so that either may be tiny or huge.
  const double lu = sxy > 0 ? 2.0 / s.b * std::log2(sxy) : -INFINITY;
  const double lw = az > 0 ? 2.0 / s.c * std::log2(az) : -INFINITY;
  const double hi = std::max(lu, lw), lo = std::min(lu, lw);
  const double e = std::exp2(lo - hi);
  const double g = std::exp2(s.b / 2.0 * (hi + std::log2(1.0 + e)));
  if (grad) {
    const double wu = lu >= lw ? 1.0 / (1.0 + e) : e / (1.0 + e), ww = 1.0 - wu;
    const double dz = az > 0 ? s.b / s.c * ww / az : 0.0;
    *grad = g * glm::dvec3(std::copysign(wu * rx, p.x), std::copysign(wu * ry, p.y), std::copysign(dz, p.z));
  }
  return g;
}

}  // namespace tg::tensor
