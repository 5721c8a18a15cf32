#pragma once
// What the renderer chooses per GL implementation, each choice measured on
// the implementation it applies to and keyed by its GL_RENDERER string;
// implementations not measured keep the plain path (docs/performance.md, "Where a
// llvmpipe frame goes"). GL-free, so that each choice is testable by name.
#include <cstdint>
#include <limits>
#include <string_view>

namespace tg::render {

struct RendererProfile {
  // No limit on glyphs per submission: one draw call (QuadSprites::kWholeDraw).
  static constexpr std::uint32_t kWholeDraw = UINT32_MAX;

  // The typical sprite width (typicalSpritePx, render/sprite_primitive.h)
  // from which quads along the glyphs' projected axes (shaders/lib/sprite.glsl)
  // cost a frame less than point sprites: they run the vertex stage four
  // times per glyph instead of once, and save fragments by the glyph's area.
  double orientedQuadMinPx = std::numeric_limits<double>::infinity();
  // The typical sprite width below which a frame culls glyphs that no pixel
  // centre can see before the draw (GlyphCulling, shaders/cull_pixels.comp).
  double pixelCullMaxPx = 0.0;
  // The typical sprite width from which the superquadric occlusion pre-pass
  // (docs/design.md, "Occlusion of superquadrics") pays.
  double occlusionMinPx = 0.0;
  // Glyphs per draw submission (QuadSprites).
  std::uint32_t glyphsPerSubmit = kWholeDraw;

  // The defaults above are the plain path, for renderers not measured.
  static RendererProfile of(std::string_view glRenderer);
};

}  // namespace tg::render
