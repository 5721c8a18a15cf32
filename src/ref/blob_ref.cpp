#include "ref/blob_ref.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "ref/pixel_loop.h"
#include "tensor/superquadric.h"

namespace tg::ref {
namespace {

using tensor::SuperquadricShape;

struct Bump {
  detail::Prepared q;  // frame and axes in GC order (z the symmetry axis); radius: where D_i falls to 1e-12 T
  SuperquadricShape shape;
  double minAxis;
};

// D_i at x and, with grad, its WC gradient added to *grad.
double bumpAt(const Bump& b, double blobbiness, const glm::dvec3& x, glm::dvec3* grad) {
  glm::dvec3 p;
  for (int k = 0; k < 3; ++k) p[k] = glm::dot(b.q.frame[k], x - b.q.centre) / b.q.axes[k];
  glm::dvec3 dg2;
  double g2;
  if (tensor::isEllipsoid(b.shape)) {
    g2 = glm::dot(p, p);
    dg2 = 2.0 * p;
  } else {
    glm::dvec3 gg;
    const double g = tensor::superquadricGauge(b.shape, p, &gg);
    g2 = g * g;
    dg2 = 2.0 * g * gg;
  }
  const double d = std::exp(blobbiness * (g2 - 1.0));
  if (grad)
    for (int k = 0; k < 3; ++k) *grad += b.q.frame[k] * (d * blobbiness * dg2[k] / b.q.axes[k]);
  return d;
}

std::vector<Bump> prepare(std::span<const tensor::GlyphRecord> glyphs, const RefParams& p, double gamma) {
  std::vector<Bump> bumps;
  // exp(B (s - 1)) = 1e-12 T at s = 1 + ln(1e-12 T) / B.
  const double s = 1.0 + std::log(1e-12 * p.blobThreshold) / p.blobBlobbiness;
  if (!(s > 0.0)) return bumps;
  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    const tensor::GlyphRecord& g = glyphs[i];
    if (!(g.fa >= p.faMin)) continue;
    glm::dvec3 axes = tensor::glyphAxes(g, p.scale, p.sizing);
    const double longest = std::max({axes.x, axes.y, axes.z});
    if (!(longest > 0.0)) continue;
    axes = glm::max(axes, glm::dvec3(tensor::kBlobMinAxisRatio * longest));
    Bump b;
    b.shape = gamma > 0.0 ? tensor::superquadricShape(glm::dvec3(g.eigenvalues[0], g.eigenvalues[1], g.eigenvalues[2]), gamma)
                          : SuperquadricShape{};
    glm::dvec3 frame[3];
    tensor::frameAxes(g, frame);
    for (int k = 0; k < 3; ++k) {
      const int src = (b.shape.axis + 1 + k) % 3;
      b.q.frame[k] = frame[src];
      b.q.axes[k] = axes[src];
    }
    b.q.centre = glm::dvec3(g.posWC[0], g.posWC[1], g.posWC[2]);
    // Every shape lies within the cube's corner, sqrt(3) of the unit (the
    // quadric within the unit); g is homogeneous of degree 1.
    b.q.radius = std::sqrt((tensor::isEllipsoid(b.shape) ? 1.0 : 3.0) * s) * std::max({axes.x, axes.y, axes.z});
    b.q.id = g.id;
    b.q.index = bumps.size();
    b.minAxis = std::min({axes.x, axes.y, axes.z});
    bumps.push_back(b);
  }
  return bumps;
}

double goldenMaximum(const auto& f, double a, double b) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), d = a + r * (b - a), fc = f(c), fd = f(d);
  for (int k = 0; k < 80 && b - a > 1e-14 * std::max(1.0, std::abs(b)); ++k) {
    if (fc > fd) {
      b = d, d = c, fd = fc, c = b - r * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd, d = a + r * (b - a), fd = f(d);
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

double blobSum(std::span<const tensor::GlyphRecord> glyphs, const RefParams& p, double gamma, const glm::dvec3& xWC) {
  double d = 0.0;
  for (const Bump& b : prepare(glyphs, p, gamma)) d += bumpAt(b, p.blobBlobbiness, xWC, nullptr);
  return d;
}

RefImage renderBlobs(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs, const RefParams& p,
                     double gamma) {
  const std::vector<Bump> bumps = prepare(glyphs, p, gamma);
  std::vector<detail::Prepared> prep;
  for (const Bump& b : bumps) prep.push_back(b.q);
  RefImage img = detail::emptyImage(cam);
  const auto tiles = detail::binGlyphs(cam, prep);
  const int tilesX = (cam.width + detail::kTile - 1) / detail::kTile;
  const glm::dmat4 wcFromVC = glm::inverse(cam.viewWCVC);
  const double T = p.blobThreshold, B = p.blobBlobbiness;
  auto rows = [&](int r0, int r1) {
    std::vector<std::uint32_t> near;
    std::vector<std::pair<double, double>> reach;  // each near bump's sphere along the ray
    struct Core {
      double t0, t1, step;
      bool operator<(const Core& o) const { return t0 < o.t0; }
    };
    std::vector<Core> cores;
    for (int j = r0; j < r1; ++j)
      for (int i = 0; i < cam.width; ++i) {
        const render::RayWC ray = cam.rayThroughPixel(i + 0.5, j + 0.5, wcFromVC);
        const double dd = glm::dot(ray.direction, ray.direction);
        // The bumps whose 1e-12 T spheres the ray crosses: every one the sum counts.
        near.clear();
        reach.clear();
        for (const std::uint32_t g : tiles[std::size_t(j / detail::kTile) * tilesX + i / detail::kTile]) {
          const Bump& b = bumps[g];
          const glm::dvec3 oc = ray.origin - b.q.centre;
          const double tc = -glm::dot(oc, ray.direction) / dd;
          const glm::dvec3 perp = oc + tc * ray.direction;
          const double h = b.q.radius * b.q.radius - glm::dot(perp, perp);
          if (h < 0.0) continue;
          near.push_back(g);
          const double half = std::sqrt(h / dd);
          reach.push_back({tc - half, tc + half});
        }
        if (near.empty()) continue;
        // Where the sum reaches T, some bump gives T / K of it (K the bumps
        // counted): the surface lies in the union of those cores (g^2 <=
        // 1 + ln(1 / K) / B, within sqrt(3) of that gauge for any shape).
        const double sCore = 1.0 + std::log(T / double(near.size())) / B;
        if (!(sCore > 0.0)) continue;
        cores.clear();
        for (const std::uint32_t g : near) {
          const Bump& b = bumps[g];
          const double r = std::sqrt((tensor::isEllipsoid(b.shape) ? 1.0 : 3.0) * sCore);
          glm::dvec3 o, d;
          for (int k = 0; k < 3; ++k) {
            o[k] = glm::dot(b.q.frame[k], ray.origin - b.q.centre) / (b.q.axes[k] * r);
            d[k] = glm::dot(b.q.frame[k], ray.direction) / (b.q.axes[k] * r);
          }
          double t0, t1;
          if (!detail::unitSphereRoots(o, d, t0, t1) || t1 < cam.nearVC) continue;
          cores.push_back({std::max(t0, cam.nearVC), t1, b.minAxis / 16.0});
        }
        if (cores.empty()) continue;
        std::sort(cores.begin(), cores.end());
        auto f = [&](double t) {
          const glm::dvec3 x = ray.origin + t * ray.direction;
          double d = 0.0;
          for (std::size_t k = 0; k < near.size(); ++k)
            if (t >= reach[k].first && t <= reach[k].second) d += bumpAt(bumps[near[k]], B, x, nullptr);
          return d - T;
        };
        const double len = std::sqrt(dd);
        // The cores front to back, merged where they overlap, each sampled
        // at a 16th of the thinnest of their bumps; a local maximum between
        // samples may cross T unseen.
        double a = 0, b = 0;
        bool found = false, inside = false;
        for (std::size_t c = 0; c < cores.size() && !found;) {
          double lo = cores[c].t0, hi = cores[c].t1, step = cores[c].step;
          for (++c; c < cores.size() && cores[c].t0 <= hi; ++c) hi = std::max(hi, cores[c].t1), step = std::min(step, cores[c].step);
          const int samples = int(std::clamp(std::ceil((hi - lo) * len / step), 8.0, 1e6));
          const double dt = (hi - lo) / samples;
          double prev = lo, fPrev = f(lo), fPrevPrev = -INFINITY;
          if (fPrev >= 0.0) {
            // The core's start inside: at the near plane only (elsewhere the sum there is below T).
            inside = true;
          }
          for (int k = 1; k <= samples && !found; ++k) {
            const double u = lo + dt * k, fu = f(u);
            if ((fu >= 0.0) != inside) {
              a = prev, b = u, found = true;
            } else if (!inside && fPrev > fPrevPrev && fPrev > fu) {
              const double from = std::max(lo, prev - dt), m = goldenMaximum(f, from, u);
              if (f(m) >= 0.0) a = from, b = m, found = true;
            }
            fPrevPrev = fPrev, fPrev = fu, prev = u;
          }
          if (inside && !found) break;  // no exit within this core: look no farther
        }
        if (!found) continue;
        const double fa = f(a);
        for (int k = 0; k < 200 && b - a > 1e-12 * b; ++k) {
          const double m = 0.5 * (a + b), fm = f(m);
          ((fm >= 0.0) == (fa >= 0.0) ? a : b) = m;
        }
        const double t = b;
        const glm::dvec3 x = ray.origin + t * ray.direction;
        glm::dvec3 grad(0.0);
        double best = -1.0;
        std::uint32_t id = kNoGlyph;
        for (const std::uint32_t g : near) {
          const double d = bumpAt(bumps[g], B, x, &grad);
          if (d > best) best = d, id = bumps[g].q.id;
        }
        const std::size_t px = std::size_t(j) * cam.width + i;
        img.depth[px] = t;
        img.normalWC[px] = glm::length(grad) > 0.0 ? -glm::normalize(grad) : glm::dvec3(0.0);
        img.id[px] = id;
      }
  };
  const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(rows, cam.height * k / threads, cam.height * (k + 1) / threads);
  rows(0, cam.height / threads);
  for (auto& th : pool) th.join();
  return img;
}

}  // namespace tg::ref
