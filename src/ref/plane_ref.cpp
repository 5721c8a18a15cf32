#include "ref/plane_ref.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace tg::ref {

void addPlane(RefImage& img, const render::Camera& cam, const render::PlaneQuad& q, std::uint32_t id,
              double offsetWC, const render::UnderlayVolume* volume) {
  const glm::dmat4 wcFromVC = glm::inverse(cam.viewWCVC);
  const glm::dvec3 n = q.normalWC, c0 = q.cornersWC[0];
  const glm::dvec3 e1 = q.cornersWC[1] - c0, e3 = q.cornersWC[3] - c0;
  // The dual basis of the quad's edges: (s, t) in [0, 1]^2 inside.
  const double g11 = glm::dot(e1, e1), g13 = glm::dot(e1, e3), g33 = glm::dot(e3, e3);
  const double det = g11 * g33 - g13 * g13;
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) {
      const render::RayWC ray = cam.rayThroughPixel(i + 0.5, j + 0.5, wcFromVC);
      const double nd = glm::dot(n, ray.direction);
      if (nd == 0.0) continue;
      const double t = glm::dot(n, q.pointWC - ray.origin) / nd;
      if (!(t >= cam.nearVC)) continue;
      const glm::dvec3 h = ray.origin + t * ray.direction - c0;
      const double a = glm::dot(h, e1), b = glm::dot(h, e3);
      const double s = (g33 * a - g13 * b) / det, u = (g11 * b - g13 * a) / det;
      if (!(s >= 0 && s <= 1 && u >= 0 && u <= 1)) continue;
      if (volume && !volume->sample(h + c0, false)) continue;
      // The ray meets the plane from the side its normal faces when n·d < 0.
      const glm::dvec3 facing = nd < 0 ? n : -n;
      const double depth = t + offsetWC / std::abs(nd);
      const std::size_t k = std::size_t(j) * std::size_t(img.width) + std::size_t(i);
      if (depth < img.depth[k]) {
        img.depth[k] = depth;
        img.id[k] = id;
        img.normalWC[k] = facing;
      }
    }
}

}  // namespace tg::ref
