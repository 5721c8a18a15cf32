#include "ref/superquadric_ref.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "ref/pixel_loop.h"

namespace tg::ref {
namespace {

using tensor::SuperquadricShape;

// The ray's span inside the cube [-1, 1]^3, which holds every glyph shape
// (g >= max-norm for c = b; g >= |z|^(b/c) = 1 on the z faces otherwise).
bool clipToCube(const glm::dvec3& o, const glm::dvec3& d, double& t0, double& t1) {
  t0 = -INFINITY;
  t1 = INFINITY;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (std::abs(o[k]) > 1.0) return false;
      continue;
    }
    const double a = (-1.0 - o[k]) / d[k], b = (1.0 - o[k]) / d[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  return t0 <= t1;
}

// Convex along every line when g is a norm: exponents 2/a, 2/b >= 1 and c = b.
bool isConvex(const SuperquadricShape& s) { return s.a <= 2.0 && s.b <= 2.0 && s.c == s.b; }

// Bisection on a sign change of h between lo and hi, to 1e-12 in t (GC units
// along d are O(1): the cube is 2 wide).
template <class H>
double bisect(H h, double lo, double hi) {
  const bool loPositive = h(lo) > 0.0;
  for (int k = 0; k < 200 && hi - lo > 1e-12 * std::max(1.0, std::abs(lo)); ++k) {
    const double mid = 0.5 * (lo + hi);
    ((h(mid) > 0.0) == loPositive ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Golden-section search for a minimum of h on [a, b] (unimodal there), to
// 1e-13; stops early at a point with h <= 0, which is all a caller needs.
template <class H>
double goldenMinimum(H h, double a, double b) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), e = a + r * (b - a);
  double hc = h(c), he = h(e);
  for (int k = 0; k < 200 && b - a > 1e-13; ++k) {
    if (hc <= 0.0 || he <= 0.0) break;
    if (hc < he) {
      b = e; e = c; he = hc; c = b - r * (b - a); hc = h(c);
    } else {
      a = c; c = e; hc = he; e = a + r * (b - a); he = h(e);
    }
  }
  return hc <= he ? c : e;
}

}  // namespace

bool superquadricFirstHit(const SuperquadricShape& s, const glm::dvec3& o, const glm::dvec3& d, double tNear,
                          double& t) {
  double t0, t1;
  if (!clipToCube(o, d, t0, t1)) return false;
  const bool fromNearPlane = tNear > t0;
  t0 = std::max(t0, tNear);
  if (t0 > t1) return false;
  auto h = [&](double u) { return tensor::superquadricGauge(s, o + u * d) - 1.0; };
  if (h(t0) <= 0.0) {
    // On the cube's face, the glyph touches the face (box-like shapes): hit.
    // At the near plane, the near point is inside: the exit, where h(t1) >= 0.
    if (!fromNearPlane) {
      t = t0;
      return true;
    }
    if (!(h(t1) > 0.0)) return false;
    t = bisect(h, t0, t1);
    return true;
  }
  if (isConvex(s)) {
    // Convex h: a root exists only if its minimum is <= 0, and it is then the
    // unique one before the minimum.
    const double tMin = goldenMinimum(h, t0, t1);
    if (h(tMin) > 0.0) return false;
    t = bisect(h, t0, tMin);
    return true;
  }
  // Non-convex (concave) shapes: the first sign change on a fine grid. A
  // spike thinner than a grid step shows as a sampled local minimum of h; its
  // true minimum, found by golden section between the neighbouring samples,
  // closes the bracket when it is <= 0.
  constexpr int kSteps = 2048;
  const double step = (t1 - t0) / kSteps;
  double prev = t0, hPrev = h(t0), hPrevPrev = INFINITY;
  for (int k = 1; k <= kSteps; ++k) {
    const double u = t0 + step * k, hu = h(u);
    if (hu <= 0.0) {
      t = bisect(h, prev, u);
      return true;
    }
    if (hPrev < hPrevPrev && hPrev < hu) {
      // Not before t0: a root there lies before the near plane or the cube.
      const double a = std::max(t0, prev - step), m = goldenMinimum(h, a, u);
      if (h(m) <= 0.0) {
        t = bisect(h, a, m);
        return true;
      }
    }
    hPrevPrev = hPrev;
    hPrev = hu;
    prev = u;
  }
  return false;
}

RefImage renderSuperquadrics(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs,
                             const RefParams& p, double gamma) {
  std::vector<detail::Prepared> prep;
  std::vector<SuperquadricShape> shapes;
  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    const auto& g = glyphs[i];
    if (!(g.fa >= p.faMin)) continue;
    const glm::dvec3 axes = tensor::glyphAxes(g, p.scale, p.sizing);
    if (!(std::max({axes.x, axes.y, axes.z}) > 0.0)) continue;
    detail::Prepared q;
    q.radius = glm::length(axes);  // the box's half diagonal
    q.centre = glm::dvec3(g.posWC[0], g.posWC[1], g.posWC[2]);
    const SuperquadricShape s =
        tensor::superquadricShape(glm::dvec3(g.eigenvalues[0], g.eigenvalues[1], g.eigenvalues[2]), gamma);
    glm::dvec3 frame[3];
    tensor::frameAxes(g, frame);
    // GC z follows the symmetry axis; a cyclic permutation keeps the frame right-handed.
    for (int k = 0; k < 3; ++k) {
      const int src = (s.axis + 1 + k) % 3;
      q.frame[k] = frame[src];
      q.axes[k] = axes[src];
    }
    q.id = g.id;
    q.index = shapes.size();
    shapes.push_back(s);
    prep.push_back(q);
  }
  return detail::castRays(cam, prep,
                          [&](const detail::Prepared& q, const glm::dvec3& o, const glm::dvec3& d, double tNear,
                              double tBest, double& t, glm::dvec3& nGC) {
                            const SuperquadricShape& s = shapes[q.index];
                            const bool ellipsoid = tensor::isEllipsoid(s);
                            if (ellipsoid) {
                              double t0, t1;
                              if (!detail::unitSphereRoots(o, d, t0, t1)) return false;
                              t = t0 >= tNear ? t0 : t1;
                            } else if (!superquadricFirstHit(s, o, d, tNear, t)) {
                              return false;
                            }
                            if (!(t >= tNear) || !(t < tBest)) return false;
                            if (ellipsoid) nGC = o + t * d;
                            else tensor::superquadricGauge(s, o + t * d, &nGC);
                            return true;
                          });
}

}  // namespace tg::ref
