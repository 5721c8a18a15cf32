#pragma once
// The reference ray casters' shared pixel loop: every pixel against the
// prepared glyphs binned to its tile, nearest hit at or beyond the near plane
// wins. Internal to src/ref.
#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

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

// Glyph `g` (input index `index`) at p's scale and sizing: false where the
// FA threshold hides it or its size is zero or not finite.
inline bool prepareGlyph(const tensor::GlyphRecord& g, const RefParams& p, std::size_t index, Prepared& q) {
  if (!(g.fa >= p.faMin)) return false;
  q.axes = tensor::glyphAxes(g, p.scale, p.sizing);
  q.radius = std::max({q.axes.x, q.axes.y, q.axes.z});
  if (!(q.radius > 0.0)) return false;
  q.centre = glm::dvec3(g.posWC[0], g.posWC[1], g.posWC[2]);
  tensor::frameAxes(g, q.frame);
  q.id = g.id;
  q.index = index;
  return true;
}

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

// Screen tiles of kTile x kTile pixels, each listing (in input order, so that
// ties resolve as in an unbinned loop) the glyphs whose bounding sphere may
// cover it. The sphere's bounding cube is projected exactly as
// Camera::rayThroughPixel inverts it; a cube reaching the eye plane covers
// the whole screen. Binning only skips glyphs no ray of a tile can reach.
inline constexpr int kTile = 16;

inline std::vector<std::vector<std::uint32_t>> binGlyphs(const render::Camera& cam,
                                                         const std::vector<Prepared>& prep) {
  const int tx = (cam.width + kTile - 1) / kTile, ty = (cam.height + kTile - 1) / kTile;
  std::vector<std::vector<std::uint32_t>> tiles(std::size_t(tx) * ty);
  const bool persp = cam.desc.projection == render::Projection::Perspective;
  const double aspect = double(cam.width) / double(cam.height);
  const double halfH = persp ? std::tan(glm::radians(cam.desc.fovYDeg) * 0.5) : 0.5 * cam.desc.orthoHeight;
  for (std::size_t g = 0; g < prep.size(); ++g) {
    const Prepared& q = prep[g];
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    bool full = false;
    for (int k = 0; k < 8 && !full; ++k) {
      const glm::dvec3 c = q.centre + q.radius * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
      const glm::dvec3 v(cam.viewWCVC * glm::dvec4(c, 1.0));
      const double w = persp ? -v.z : 1.0;
      if (!(w > 0.0)) {
        full = true;
        break;
      }
      const double xn = v.x / (w * halfH * aspect), yn = v.y / (w * halfH);
      const double px = 0.5 * (xn + 1.0) * cam.width, py = 0.5 * (1.0 - yn) * cam.height;
      x0 = std::min(x0, px), x1 = std::max(x1, px), y0 = std::min(y0, py), y1 = std::max(y1, py);
    }
    // Pixel centres within the rectangle, widened by a pixel against rounding.
    const auto tileOf = [](double p, int n) { return int(std::clamp(std::floor(p / kTile), 0.0, double(n - 1))); };
    if (!full && (x1 < -1.0 || y1 < -1.0 || x0 > cam.width + 1.0 || y0 > cam.height + 1.0)) continue;
    const int i0 = full ? 0 : tileOf(x0 - 1.0, tx), i1 = full ? tx - 1 : tileOf(x1 + 1.0, tx);
    const int j0 = full ? 0 : tileOf(y0 - 1.0, ty), j1 = full ? ty - 1 : tileOf(y1 + 1.0, ty);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) tiles[std::size_t(j) * tx + i].push_back(std::uint32_t(g));
  }
  return tiles;
}

// intersect(q, oGC, dGC, tNear, tBest, t, nGC) -> bool: the first surface point
// of glyph q along o + t d with tNear <= t < tBest, and its GC gradient.
// The camera's image, every pixel empty.
inline RefImage emptyImage(const render::Camera& cam) {
  RefImage img;
  img.width = cam.width;
  img.height = cam.height;
  const std::size_t n = std::size_t(cam.width) * cam.height;
  img.depth.assign(n, INFINITY);
  img.normalWC.assign(n, glm::dvec3(0.0));
  img.id.assign(n, kNoGlyph);
  return img;
}

template <class Intersect>
RefImage castRays(const render::Camera& cam, const std::vector<Prepared>& prep, Intersect intersect) {
  RefImage img = emptyImage(cam);
  const auto tiles = binGlyphs(cam, prep);
  const int tilesX = (cam.width + kTile - 1) / kTile;
  const glm::dmat4 wcFromVC = glm::inverse(cam.viewWCVC);
  auto rows = [&](int r0, int r1) {
    for (int j = r0; j < r1; ++j)
      for (int i = 0; i < cam.width; ++i) {
        const render::RayWC ray = cam.rayThroughPixel(i + 0.5, j + 0.5, wcFromVC);
        const double dd = glm::dot(ray.direction, ray.direction);
        const std::size_t px = std::size_t(j) * cam.width + i;
        for (const std::uint32_t g : tiles[std::size_t(j / kTile) * tilesX + i / kTile]) {
          const Prepared& q = prep[g];
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
