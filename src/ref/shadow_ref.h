#pragma once
// The CPU reference for key-light shadows: from each visible surface point of
// a reference image, an exact double-precision shadow ray towards the key
// light (a directional light) against every ellipsoid. The GL tests compare
// the GPU's filtered shadow map with it pixel by pixel.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "ref/ellipsoid_ref.h"

namespace tg::ref {

enum class KeyLight : std::uint8_t {
  None,      // empty, or the surface faces away from the light (no key light to shadow)
  Lit,       // the shadow ray reaches the light
  Shadowed,  // another glyph is in the way
};

// A glyph never shadows the point it was hit at: ellipsoids are convex, and
// the point faces the light (n·l > minCos).
class ShadowRays {
 public:
  ShadowRays(std::span<const tensor::GlyphRecord> glyphs, const RefParams& p, const glm::dvec3& keyDirWC);
  // Whether the ray from pointWC towards the light hits a glyph other than `self` (an id).
  bool blocked(const glm::dvec3& pointWC, std::uint32_t self) const;
  // Lit or Shadowed at each covered pixel of `img` (rendered with `cam`)
  // whose normal has n·l > minCos; None elsewhere.
  std::vector<KeyLight> classify(const render::Camera& cam, const RefImage& img, double minCos) const;
  // True when the shadow rays from points of pixel k's tangent plane, offset
  // by radius r and r/2 across the light in 16 directions, do not all agree
  // with its own: the pixel lies in a penumbra of width about 2r.
  bool nearShadowEdge(const render::Camera& cam, const RefImage& img, std::size_t k, double r) const;
  const glm::dvec3& keyDirWC() const { return l_; }

 private:
  glm::dvec3 pointOf(const render::Camera& cam, const RefImage& img, std::size_t k) const;
  struct Glyph {
    glm::dvec3 centre, axes, frame[3];
    double radius;
    std::uint32_t id;
  };
  std::vector<Glyph> glyphs_;
  glm::dvec3 l_;
};

}  // namespace tg::ref
