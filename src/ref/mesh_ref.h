#pragma once
// The CPU reference for context meshes (render/mesh_item.h): exact
// double-precision ray-triangle intersection over the same pixel rays as the
// ellipsoid reference, so that a glyph half through a mesh can be compared
// with the GPU's depth mixing. Shares no arithmetic with the GPU path.
#include <cstdint>
#include <optional>
#include <span>

#include <glm/vec3.hpp>

#include "ref/ellipsoid_ref.h"
#include "view/camera.h"

namespace tg::ref {

// The ray parameter t >= tNear (the depth along the view axis, as the ray's
// direction has a unit view component) where o + t d meets triangle abc,
// edges included; none for a ray in the triangle's plane or a degenerate triangle.
std::optional<double> rayTriangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                                  const glm::dvec3& c, double tNear);

// Adds an opaque mesh to `img` (say, renderEllipsoids' output for `cam`):
// each pixel whose ray meets a triangle nearer than what the image holds
// takes the triangle's depth, its normal (facing the ray) and `id`.
// `positionsWC`: 3 per vertex; `triangles`: 3 vertex indices each.
void addTriangles(RefImage& img, const render::Camera& cam, std::span<const float> positionsWC,
                  std::span<const std::uint32_t> triangles, std::uint32_t id);

}  // namespace tg::ref
