#pragma once
// Blinn's blobs cast on the CPU (GlyphKind::Blob; Blinn 1982 §3.3-3.6):
// one pass over all cores sets up each glyph's truncated bump
// (shaders/lib/blob.glsl's blobBump, compiled as C++) and bins its region's
// pixel rectangle to screen tiles, which serve as Blinn's x/y active lists;
// per pixel, the bumps whose regions the ray crosses (his z-active list) are
// swept front to back. The sum is sampled at each bump's entry, peak and
// exit and `steps` times between them; the first change of sign of
// sum - T is refined by Illinois regula falsi (Blinn's hybrid, with a
// bracket kept throughout). The hit's record is its dominant bump's
// (largest D'_i): colour, id and picking follow it; the normal is the
// sum's gradient. Fills CpuCasts as castGlyphs does, so that the deferred
// passes run unchanged.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/cpu_glyphs.h"

namespace tg::render {

struct BlobCandidate {
  glm::vec3 centreVC;
  glm::mat3 gcFromVC;
  glm::vec4 shape;
  float reachGC, nearVC;
  std::uint32_t record;
};

// The casts of `cam` at p's parameters (p.gamma, p.blob) over `records` on
// `threads` threads into `out` (windowDepth, record, normalWC and, with
// `hitGC`, the dominant bump's GC point in its ellipsoid's axis order).
// `bumps` holds the set-up between frames. Returns the bumps that reached a tile.
std::uint64_t castBlobs(std::span<const tensor::GlyphRecord> records, const Camera& cam, const FrameParams& p,
                        bool hitGC, int threads, CpuCasts& out, std::vector<BlobCandidate>& bumps);

}  // namespace tg::render
