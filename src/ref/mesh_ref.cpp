#include "ref/mesh_ref.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace tg::ref {

// Möller and Trumbore (1997) in double precision, edges inclusive.
std::optional<double> rayTriangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                                  const glm::dvec3& c, double tNear) {
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0 || !std::isfinite(det)) return std::nullopt;
  const double inv = 1.0 / det;
  const glm::dvec3 s = o - a;
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = glm::dot(e2, q) * inv;
  if (!(t >= tNear)) return std::nullopt;
  return t;
}

void addTriangles(RefImage& img, const render::Camera& cam, std::span<const float> positionsWC,
                  std::span<const std::uint32_t> triangles, std::uint32_t id) {
  const glm::dmat4 wcFromVC = glm::inverse(cam.viewWCVC);
  auto vertex = [&](std::uint32_t i) {
    return glm::dvec3(positionsWC[3 * std::size_t(i)], positionsWC[3 * std::size_t(i) + 1],
                      positionsWC[3 * std::size_t(i) + 2]);
  };
  for (int j = 0; j < cam.height; ++j)
    for (int i = 0; i < cam.width; ++i) {
      const render::RayWC ray = cam.rayThroughPixel(i + 0.5, j + 0.5, wcFromVC);
      const std::size_t px = std::size_t(j) * std::size_t(cam.width) + std::size_t(i);
      for (std::size_t k = 0; k + 2 < triangles.size(); k += 3) {
        const glm::dvec3 a = vertex(triangles[k]), b = vertex(triangles[k + 1]), c = vertex(triangles[k + 2]);
        const auto t = rayTriangle(ray.origin, ray.direction, a, b, c, cam.nearVC);
        if (!t || !(*t < img.depth[px])) continue;
        glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        if (glm::dot(n, ray.direction) > 0.0) n = -n;
        img.depth[px] = *t;
        img.normalWC[px] = n;
        img.id[px] = id;
      }
    }
}

}  // namespace tg::ref
