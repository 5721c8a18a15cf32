#pragma once
// The CPU reference for Teem's cylinder and box glyphs (render::GlyphKind
// Cylinder, Box): exact double-precision ray casts, sharing the camera, the
// glyph record and the sizing with the GPU path, none of its arithmetic.
#include <span>

#include "ref/ellipsoid_ref.h"

namespace tg::ref {

// Teem's tenGlyphGen (teem/src/ten/glyph.c, "find axis"): the eigenvector
// index (0 major, 2 minor) its cylinder runs along, transcribed branch by
// branch: positive tensors by Westin's cl1 > cp1 (clamped to 0.99), negative
// ones by the same on the reversed |eigenvalues|, mixed signs or zeros by
// Schultz & Kindlmann 2010's zones.
int teemCylinderAxis(const glm::dvec3& eigenvalues);

// The ray o + t d (GC) against the unit cylinder x^2 + y^2 <= 1, |z| <= 1 or
// the cube [-1, 1]^3: the first surface point with t >= tNear (from inside,
// the exit) and its GC normal. False on a miss.
bool cylinderFirstHit(const glm::dvec3& o, const glm::dvec3& d, double tNear, double& t, glm::dvec3& nGC);
bool boxFirstHit(const glm::dvec3& o, const glm::dvec3& d, double tNear, double& t, glm::dvec3& nGC);

// Semi-axes |eigenvalue| x the glyph's factor, as ellipsoids (p.sizing).
RefImage renderCylinders(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs, const RefParams& p);
RefImage renderBoxes(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs, const RefParams& p);

}  // namespace tg::ref
