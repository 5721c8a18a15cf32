#pragma once
// The CPU reference for superquadric glyphs: double precision, with every
// root bracketed and bisected to 1e-12 of the glyph size. It is the oracle
// of the GPU's Newton march, so it shares the shape mapping and the implicit
// function (src/tensor/superquadric.h) but none of the root finding.
#include <span>

#include "ref/ellipsoid_ref.h"
#include "tensor/superquadric.h"

namespace tg::ref {

// Glyphs whose shape at `gamma` is an ellipsoid take the exact quadric path.
RefImage renderSuperquadrics(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs,
                             const RefParams& p, double gamma);

// The first crossing of the unit glyph g(p) = 1 along o + t d (GC) with
// t >= tNear: an entry, or from inside the glyph its exit. False if none.
bool superquadricFirstHit(const tensor::SuperquadricShape& s, const glm::dvec3& o, const glm::dvec3& d,
                          double tNear, double& t);

}  // namespace tg::ref
