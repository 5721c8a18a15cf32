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
  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    const auto& g = glyphs[i];
    if (!(g.fa >= p.faMin)) continue;
    detail::Prepared q;
    q.axes = tensor::glyphAxes(g, p.scale, p.sizing);
    q.radius = std::max({q.axes.x, q.axes.y, q.axes.z});
    if (!(q.radius > 0.0)) continue;
    q.centre = glm::dvec3(g.posWC[0], g.posWC[1], g.posWC[2]);
    tensor::frameAxes(g, q.frame);
    q.id = g.id;
    q.index = i;
    prep.push_back(q);
  }
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
