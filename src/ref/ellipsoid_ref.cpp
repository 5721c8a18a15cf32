#include "ref/ellipsoid_ref.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include <glm/geometric.hpp>

namespace tg::ref {
namespace {

struct Prepared {
  glm::dvec3 centre, axes;
  glm::dvec3 frame[3];
  double radius;
  std::uint32_t id;
};

// Roots of |o + t d|^2 = 1 (a ray against the unit sphere), from the closest
// approach to the centre so that neither root suffers cancellation.
bool unitSphereRoots(const glm::dvec3& o, const glm::dvec3& d, double& t0, double& t1) {
  const double dd = glm::dot(d, d);
  const double tc = -glm::dot(o, d) / dd;
  const glm::dvec3 q = o + tc * d;
  const double h = 1.0 - glm::dot(q, q);
  if (h < 0.0) return false;
  const double s = std::sqrt(h / dd);
  t0 = tc - s;
  t1 = tc + s;
  return true;
}

}  // namespace

RefImage renderEllipsoids(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs,
                          const RefParams& p) {
  std::vector<Prepared> prep;
  for (const auto& g : glyphs) {
    if (!(g.fa >= p.faMin)) continue;
    Prepared q;
    q.axes = tensor::ellipsoidAxes(g, p.scale);
    q.radius = std::max({q.axes.x, q.axes.y, q.axes.z});
    if (!(q.radius > 0.0)) continue;
    q.centre = glm::dvec3(g.posWC[0], g.posWC[1], g.posWC[2]);
    tensor::frameAxes(g, q.frame);
    q.id = g.id;
    prep.push_back(q);
  }
  RefImage img;
  img.width = cam.width;
  img.height = cam.height;
  const std::size_t n = std::size_t(cam.width) * cam.height;
  img.depth.assign(n, INFINITY);
  img.normalWC.assign(n, glm::dvec3(0.0));
  img.id.assign(n, kNoGlyph);

  auto rows = [&](int r0, int r1) {
    for (int j = r0; j < r1; ++j)
      for (int i = 0; i < cam.width; ++i) {
        const render::RayWC ray = cam.rayThroughPixel(i + 0.5, j + 0.5);
        const double dd = glm::dot(ray.direction, ray.direction);
        const std::size_t px = std::size_t(j) * cam.width + i;
        for (const Prepared& q : prep) {
          const glm::dvec3 oc = ray.origin - q.centre;
          // Cheap reject against the circumscribed sphere.
          const glm::dvec3 perp = oc - glm::dot(oc, ray.direction) / dd * ray.direction;
          if (glm::dot(perp, perp) > q.radius * q.radius) continue;
          glm::dvec3 o, d;
          for (int k = 0; k < 3; ++k) {
            o[k] = glm::dot(q.frame[k], oc) / q.axes[k];
            d[k] = glm::dot(q.frame[k], ray.direction) / q.axes[k];
          }
          double t0, t1;
          if (!unitSphereRoots(o, d, t0, t1)) continue;
          // Ray parameter == depth along the view axis (unit view component).
          const double t = t0 >= cam.nearVC ? t0 : t1;
          if (!(t >= cam.nearVC) || !(t < img.depth[px])) continue;
          const glm::dvec3 nGC = o + t * d;
          glm::dvec3 nWC(0.0);
          for (int k = 0; k < 3; ++k) nWC += q.frame[k] * (nGC[k] / q.axes[k]);
          img.depth[px] = t;
          img.normalWC[px] = glm::normalize(nWC);
          img.id[px] = q.id;
        }
      }
  };
  const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k)
    pool.emplace_back(rows, cam.height * k / threads, cam.height * (k + 1) / threads);
  rows(0, cam.height / threads);
  for (auto& t : pool) t.join();
  return img;
}

}  // namespace tg::ref
