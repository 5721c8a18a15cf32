#include "ref/shadow_ref.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "ref/pixel_loop.h"

namespace tg::ref {

ShadowRays::ShadowRays(std::span<const tensor::GlyphRecord> glyphs, const RefParams& p, const glm::dvec3& keyDirWC)
    : l_(glm::normalize(keyDirWC)) {
  // The same glyphs the reference image casts rays at (ref::renderEllipsoids).
  for (std::size_t i = 0; i < glyphs.size(); ++i)
    if (detail::Prepared q; detail::prepareGlyph(glyphs[i], p, i, q))
      glyphs_.push_back({q.centre, q.axes, {q.frame[0], q.frame[1], q.frame[2]}, q.radius, q.id});
}

bool ShadowRays::blocked(const glm::dvec3& p, std::uint32_t self) const {
  for (const Glyph& q : glyphs_) {
    if (q.id == self) continue;
    const glm::dvec3 oc = p - q.centre;
    const double along = glm::dot(oc, l_);
    // Wholly behind the point as seen from the light, or wide of the ray.
    if (along > q.radius) continue;
    const glm::dvec3 perp = oc - along * l_;
    if (glm::dot(perp, perp) > q.radius * q.radius) continue;
    glm::dvec3 o, d;
    for (int k = 0; k < 3; ++k) {
      o[k] = glm::dot(q.frame[k], oc) / q.axes[k];
      d[k] = glm::dot(q.frame[k], l_) / q.axes[k];
    }
    double t0, t1;
    if (detail::unitSphereRoots(o, d, t0, t1) && t1 > 0.0) return true;
  }
  return false;
}

glm::dvec3 ShadowRays::pointOf(const render::Camera& cam, const RefImage& img, std::size_t k) const {
  const int i = int(k % std::size_t(img.width)), j = int(k / std::size_t(img.width));
  const render::RayWC ray = cam.rayThroughPixel(i + 0.5, j + 0.5);
  return ray.origin + img.depth[k] * ray.direction;  // the direction has a unit view component
}

std::vector<KeyLight> ShadowRays::classify(const render::Camera& cam, const RefImage& img, double minCos) const {
  std::vector<KeyLight> out(img.id.size(), KeyLight::None);
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (img.id[k] == kNoGlyph || !(glm::dot(img.normalWC[k], l_) > minCos)) continue;
    out[k] = blocked(pointOf(cam, img, k), img.id[k]) ? KeyLight::Shadowed : KeyLight::Lit;
  }
  return out;
}

bool ShadowRays::nearShadowEdge(const render::Camera& cam, const RefImage& img, std::size_t k, double r) const {
  const glm::dvec3 p = pointOf(cam, img, k), n = img.normalWC[k];
  const bool own = blocked(p, img.id[k]);
  // Two axes across the light; an offset e across it moves along the light
  // by -n·e / n·l to stay on the tangent plane, which the convex glyph lies
  // wholly behind, so its own rays never meet it.
  const glm::dvec3 a = glm::normalize(std::abs(l_.x) < 0.9 ? glm::cross(l_, glm::dvec3(1, 0, 0))
                                                            : glm::cross(l_, glm::dvec3(0, 1, 0)));
  const glm::dvec3 b = glm::cross(l_, a);
  for (double radius : {r, 0.5 * r})
    for (int s = 0; s < 16; ++s) {
      const double phi = 2.0 * M_PI * s / 16.0;
      const glm::dvec3 e = radius * (std::cos(phi) * a + std::sin(phi) * b);
      const glm::dvec3 q = p + e - glm::dot(n, e) / glm::dot(n, l_) * l_;
      if (blocked(q, img.id[k]) != own) return true;
    }
  return false;
}

}  // namespace tg::ref
