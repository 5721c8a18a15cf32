// One screen-aligned quad per glyph without a geometry stage. The renderer
// draws an index pattern (0 1 2, 2 1 3) per glyph, so vertex k of glyph g has
// gl_VertexID = 4g + k; all four vertices pull the same record. Or, when
// every glyph's rectangle fits (render/sprite_primitive.h), one point sprite
// per glyph (gl_VertexID = g) whose square holds the rectangle: pixels of the
// square outside it miss the glyph as every pixel of the rectangle off its
// silhouette does.
//
// Why not the alternatives: point sprites are capped (255 px on llvmpipe,
// GL_POINT_SIZE_RANGE), and a glyph near the camera needs up to the whole
// viewport; a geometry shader expanding one point per glyph made llvmpipe
// buffer every output vertex of the draw (about 0.7 kB per glyph, measured).

// Under an FA threshold the draw walks the compacted list instead
// (compact_fa.comp): slot -> record. Off, the slot is the record.
layout(std430, binding = 2) readonly buffer KeptIndex { uint keptIndex[]; };
uniform int uCompacted;
uniform int uPointSprites;  // 1: GL_POINTS, one vertex per glyph

uint spriteGlyphIndex() {
  uint slot = uPointSprites != 0 ? uint(gl_VertexID) : uint(gl_VertexID) >> 2u;
  return uCompacted != 0 ? keptIndex[slot] : slot;
}

// Outside the clip volume: both triangles of a culled glyph are dropped
// before rasterisation.
const vec4 kSpriteCulledCC = vec4(2.0, 2.0, 2.0, 1.0);

// The corner of rectNDC (xmin, ymin, xmax, ymax) for this vertex, at window
// depth depthWin (ClipControl ZERO_TO_ONE: NDC z is window depth); for a
// point sprite, the rectangle's centre, which lies in the viewport, so the
// point is never clipped whole. Its side needs no margin: the rectangle's own
// (a quarter pixel or more) exceeds the rasteriser's snapping.
vec4 spriteCornerCC(vec4 rectNDC, float depthWin) {
  if (uPointSprites != 0) {
    vec2 sizeDC = (rectNDC.zw - rectNDC.xy) * 0.5 * uViewportDC;
    gl_PointSize = max(sizeDC.x, sizeDC.y);
    return vec4(0.5 * (rectNDC.xy + rectNDC.zw), depthWin, 1.0);
  }
  int c = gl_VertexID & 3;
  return vec4((c & 1) == 0 ? rectNDC.x : rectNDC.z, (c & 2) == 0 ? rectNDC.y : rectNDC.w, depthWin, 1.0);
}
