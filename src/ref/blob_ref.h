#pragma once
// The CPU reference for Blinn's blobs (render::GlyphKind::Blob): double
// precision and untruncated, the oracle of the cpu path's truncated, sampled
// sweep (render/cpu_blobs.h). It shares the glyph record, the shape mapping
// and the gauge (tensor/superquadric.h), none of the set-up or root finding.
//
// Each glyph contributes D_i = exp(B (g_i^2 - 1)), g_i its glyph's gauge in
// its GC (|p| for the quadric at gamma 0, else the superquadric's at gamma);
// the surface is sum_i D_i = T. Bumps are summed wherever they exceed
// 1e-12 T (beyond, its sphere: where it adds less). Along each pixel's ray the sum is sampled only where it can
// reach T (where one of the K bumps counted gives T / K), at a 16th of the
// smallest semi-axis of the bumps there; each local maximum between samples
// is found by golden section, and the first crossing is bisected to 1e-12
// of its depth. Colour and id follow the largest D_i at the hit; the
// normal is the sum's gradient.
#include <span>

#include "ref/ellipsoid_ref.h"

namespace tg::ref {

RefImage renderBlobs(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs, const RefParams& p,
                     double gamma);

// The sum at WC point x over `glyphs` (for the tests' spot checks).
double blobSum(std::span<const tensor::GlyphRecord> glyphs, const RefParams& p, double gamma, const glm::dvec3& xWC);

}  // namespace tg::ref
