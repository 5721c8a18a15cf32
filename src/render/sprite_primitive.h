#pragma once
// Which primitive carries a glyph's screen rectangle (shaders/lib/sprite.glsl),
// GL-free. A point sprite costs llvmpipe one vertex-shader run and one
// primitive set-up per glyph where a two-triangle quad costs four and two,
// and its square has no shared diagonal whose 4x4 pixel blocks are shaded
// twice. Points are capped in size (255 pixels on llvmpipe,
// GL_POINT_SIZE_RANGE), so a frame draws them only when no glyph's rectangle
// can be wider than the cap; otherwise quads.
#include <string_view>

#include <glm/vec3.hpp>

#include "render/camera.h"

namespace tg::render {

// An upper bound, in pixels, on the width and height of every sprite
// rectangle of glyphs whose centres lie in [centresLoWC, centresHiWC] and
// whose points lie within radiusWC of their centre, margins included;
// +infinity where none is known (the eye within reach of a glyph, or an
// off-centre projection).
double spriteSizeBoundPx(const Camera& cam, const glm::dvec3& centresLoWC, const glm::dvec3& centresHiWC,
                         double radiusWC);

// Whether this frame draws point sprites: every rectangle fits a point of
// at most maxPointPx pixels.
bool pointSpritesFit(const Camera& cam, const glm::dvec3& centresLoWC, const glm::dvec3& centresHiWC,
                     double radiusWC, double maxPointPx);

// The width in pixels of a glyph diameterWC across at the centre of the
// glyph centres' bounds: what a frame's typical sprite covers. +infinity
// where that centre is not in front of the eye.
double typicalSpritePx(const Camera& cam, const glm::dvec3& centresLoWC, const glm::dvec3& centresHiWC,
                       double diameterWC);

// The typical sprite width (typicalSpritePx) from which quads along the
// glyphs' projected axes (shaders/lib/sprite.glsl) cost a frame less than
// point sprites on this renderer (GL_RENDERER): they run the vertex stage
// four times per glyph instead of once, and save fragments by the glyph's
// area. Measured on llvmpipe only; +infinity (points) elsewhere until measured.
double orientedQuadMinPx(std::string_view glRenderer);

// The typical sprite width below which a frame culls glyphs that no pixel
// centre can see before the draw (GlyphCulling, shaders/cull_pixels.comp)
// on this renderer: llvmpipe runs the vertex stage on one thread, eight
// glyphs at a time, so a pass over all glyphs on every thread pays where
// most glyphs are culled. 0 (never) elsewhere: a GPU's vertex stage is
// parallel, and the pass would be a dependent dispatch per frame.
double pixelCullMaxPx(std::string_view glRenderer);

// The typical sprite width from which the superquadric occlusion pre-pass
// (README, "Occlusion of superquadrics") pays on this renderer: below it the
// pre-pass's vertex stage and depth pyramid cost more than the few
// fragments it saves. 0 (always) where not measured.
double occlusionMinPx(std::string_view glRenderer);

}  // namespace tg::render
