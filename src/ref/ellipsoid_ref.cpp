#include "ref/ellipsoid_ref.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "ref/pixel_loop.h"

namespace tg::ref {
using detail::unitSphereRoots;

RefImage renderEllipsoids(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs,
                          const RefParams& p) {
  std::vector<detail::Prepared> prep;
  for (std::size_t i = 0; i < glyphs.size(); ++i)
    if (detail::Prepared q; detail::prepareGlyph(glyphs[i], p, i, q)) prep.push_back(q);
  return detail::castRays(cam, prep,
                          [](const detail::Prepared&, const glm::dvec3& o, const glm::dvec3& d, double tNear,
                             double tBest, double& t, glm::dvec3& nGC) {
                            double t0, t1;
                            if (!unitSphereRoots(o, d, t0, t1)) return false;
                            t = t0 >= tNear ? t0 : t1;  // from inside, the far wall
                            if (!(t >= tNear) || !(t < tBest)) return false;
                            nGC = o + t * d;
                            return true;
                          });
}

}  // namespace tg::ref
