#pragma once
// Which primitive carries a glyph's screen rectangle (shaders/lib/sprite.glsl),
// GL-free. A point sprite costs llvmpipe one vertex-shader run and one
// primitive set-up per glyph where a two-triangle quad costs four and two,
// and its square has no shared diagonal whose 4x4 pixel blocks are shaded
// twice. Points are capped in size (255 pixels on llvmpipe,
// GL_POINT_SIZE_RANGE), so a frame draws them only when no glyph's rectangle
// can be wider than the cap; otherwise quads.

#include <glm/vec3.hpp>

#include "view/camera.h"

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

}  // namespace tg::render
