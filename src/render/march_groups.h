#pragma once
// Which glyph groups a frame marches, and by which march variant: the one
// rule the raster path's programs and the CPU path's casts both follow, so
// that the two paths draw each glyph with the same code.
#include <optional>

#include "render/frame_params.h"
#include "render/glyph_kind.h"
#include "tensor/glyph.h"

namespace tg::render {

// Groups below the split are cast as ellipsoids: every group for kinds that
// do not march (split 3), spheres in superquadric frames (split 1), and
// definite glyphs too at gamma 0, where they are ellipsoids (split 2).
inline int marchSplit(const FrameParams& p) {
  if (glyphKind(p.glyph).draw != KindDraw::Superquadric) return 3;
  return p.gamma > 0.0 ? 1 : 2;
}

// The variant group `group` marches with, none below the split: definite
// glyphs (all convex at gamma > 0) by the convex variant, mixed-sign ones by
// the mixed variant, or every marched group by the general march.
inline std::optional<MarchVariant> marchVariant(int group, int split, bool variants) {
  if (group < split) return std::nullopt;
  if (!variants) return MarchVariant::General;
  return group == int(tensor::GlyphGroup::Definite) ? MarchVariant::Convex : MarchVariant::Mixed;
}

}  // namespace tg::render
