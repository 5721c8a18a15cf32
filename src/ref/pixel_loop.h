#pragma once
// The reference ray casters' shared pixel loop: every pixel against every
// prepared glyph, nearest hit at or beyond the near plane wins. Internal to
// src/ref.
#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "ref/ellipsoid_ref.h"

namespace tg::ref::detail {

// A glyph in its parameter space: p_GC = (frame_k · (p_WC - centre) / axes_k)_k.
struct Prepared {
  glm::dvec3 centre, axes;
  glm::dvec3 frame[3];  // GC axes in WC
  double radius;        // of a sphere around everything the glyph can cover
  std::uint32_t id;
  std::size_t index;    // into the caller's per-glyph data
};

// Roots of |o + t d|^2 = 1 (a ray against the unit sphere), from the closest
// approach to the centre so that neither root suffers cancellation.
inline bool unitSphereRoots(const glm::dvec3& o, const glm::dvec3& d, double& t0, double& t1) {
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

// intersect(q, oGC, dGC, tNear, tBest, t, nGC) -> bool: the first surface point
// of glyph q along o + t d with tNear <= t < tBest, and its GC gradient.
template <class Intersect>
RefImage castRays(const render::Camera& cam, const std::vector<Prepared>& prep, Intersect intersect) {
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
          const glm::dvec3 perp = oc - glm::dot(oc, ray.direction) / dd * ray.direction;
          if (glm::dot(perp, perp) > q.radius * q.radius) continue;
          glm::dvec3 o, d;
          for (int k = 0; k < 3; ++k) {
            o[k] = glm::dot(q.frame[k], oc) / q.axes[k];
            d[k] = glm::dot(q.frame[k], ray.direction) / q.axes[k];
          }
          // The ray parameter is the depth along the view axis (unit view component).
          double t;
          glm::dvec3 nGC;
          if (!intersect(q, o, d, cam.nearVC, img.depth[px], t, nGC)) continue;
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

}  // namespace tg::ref::detail
