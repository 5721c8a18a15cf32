// One screen-aligned quad per glyph without a geometry stage. The renderer
// draws an index pattern (0 1 2, 2 1 3) per glyph, so vertex k of glyph g has
// gl_VertexID = 4g + k; all four vertices pull the same record.
//
// Why not the alternatives: point sprites are capped (255 px on llvmpipe,
// GL_POINT_SIZE_RANGE), and a glyph near the camera needs up to the whole
// viewport; a geometry shader expanding one point per glyph made llvmpipe
// buffer every output vertex of the draw (about 0.7 kB per glyph, measured).

// Under an FA threshold the draw walks the compacted list instead
// (compact_fa.comp): slot -> record. Off, the slot is the record.
layout(std430, binding = 2) readonly buffer KeptIndex { uint keptIndex[]; };
uniform int uCompacted;

uint spriteGlyphIndex() {
  uint slot = uint(gl_VertexID) >> 2u;
  return uCompacted != 0 ? keptIndex[slot] : slot;
}

// Outside the clip volume: both triangles of a culled glyph are dropped
// before rasterisation.
const vec4 kSpriteCulledCC = vec4(2.0, 2.0, 2.0, 1.0);

// The corner of rectNDC (xmin, ymin, xmax, ymax) for this vertex, at window
// depth depthWin (ClipControl ZERO_TO_ONE: NDC z is window depth).
vec4 spriteCornerCC(vec4 rectNDC, float depthWin) {
  int c = gl_VertexID & 3;
  return vec4((c & 1) == 0 ? rectNDC.x : rectNDC.z, (c & 2) == 0 ? rectNDC.y : rectNDC.w, depthWin, 1.0);
}
