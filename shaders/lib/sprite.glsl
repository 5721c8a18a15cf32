// One screen-aligned quad per glyph without a geometry stage. The renderer
// draws an index pattern (0 1 2, 2 1 3) per glyph, so vertex k of glyph g has
// gl_VertexID = 4g + k; all four vertices pull the same record. Or, when
// every glyph's rectangle fits (render/sprite_primitive.h), one point sprite
// per glyph (gl_VertexID = g) whose square holds the rectangle: pixels of the
// square outside it miss the glyph as every pixel of the rectangle off its
// silhouette does.
//
// Ray-cast kinds may instead draw a quad along the glyph's projected axes
// (SpriteQuadDC below) where that is smaller. Requires lib/camera.glsl and
// lib/ellipsoid.glsl.
//
// A glyph whose rectangle holds no pixel centre shades nothing, however
// drawn: its vertex stops (lib/pixel_centres.glsl) and no primitive is set up.
//
// Why not the alternatives: point sprites are capped (255 px on llvmpipe,
// GL_POINT_SIZE_RANGE), and a glyph near the camera needs up to the whole
// viewport; a geometry shader expanding one point per glyph made llvmpipe
// buffer every output vertex of the draw (about 0.7 kB per glyph, measured).
#include "lib/bindings.h"

#include "lib/pixel_centres.glsl"

// Under an FA threshold the draw walks the compacted list instead
// (compact_fa.comp): slot -> record. Off, the slot is the record.
layout(std430, binding = TG_SSBO_KEPT_INDEX) readonly buffer KeptIndex { uint keptIndex[]; };
uniform int uCompacted;
uniform int uPointSprites;  // 1: GL_POINTS, one vertex per glyph
uniform int uOrientedSprites;  // 1: quads may turn to the glyph's own axes

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

// An oriented quad in window pixels: centre, unit first axis (the second is
// its perpendicular) and half-extents along them. A thin glyph seen along a
// diagonal fills a small part of its axis-aligned rectangle; the quad along
// its own projected axes holds the same pixels that can hit and few others.
struct SpriteQuadDC {
  vec2 centre;
  vec2 axis;
  vec2 halfSize;
};

// The projected outline of the ellipsoid whose parameter->clip transform is
// pmt, as in ellipsoidRectNDC (Sigg et al. eq. 5) but along any direction:
// its tangent lines with unit window normal n lie at n.centreDC +- sqrt(n^T
// supportDC n). Returns false where it meets the eye plane.
bool ellipseSupportDC(mat4 pmt, out vec2 centreDC, out mat2 supportDC) {
  EllipseTerms e;
  if (!ellipseTerms(pmt, e)) return false;
  float a = e.a;
  vec2 x0 = e.x0, b = e.b;
  vec4 u1 = e.u1, u2 = e.u2;
  // Half-widths squared in NDC: (b_i b_j - a D(u_i, u_j)) / a^2; to pixels by k.
  vec2 k = 0.5 * uViewportDC;
  float sxx = (b.x * b.x - a * formD(u1, u1)) / (a * a), syy = (b.y * b.y - a * formD(u2, u2)) / (a * a);
  float sxy = (b.x * b.y - a * formD(u1, u2)) / (a * a);
  supportDC = mat2(max(sxx, 0.0) * k.x * k.x, sxy * k.x * k.y, sxy * k.x * k.y, max(syy, 0.0) * k.y * k.y);
  centreDC = (x0 + b / a + 1.0) * k;
  return true;
}

// The quad along the principal axes of the outline of ellipseSupportDC, the
// smallest rectangle that holds it; half-extents without margin.
SpriteQuadDC ellipseQuadDC(vec2 centreDC, mat2 supportDC) {
  float p = supportDC[0][0], q = supportDC[0][1], r = supportDC[1][1];
  // Any unit axis gives a rectangle that holds the ellipse; the principal
  // one (where defined) the smallest.
  float theta = q != 0.0 || p != r ? 0.5 * atan(2.0 * q, p - r) : 0.0;
  vec2 e = vec2(cos(theta), sin(theta)), f = vec2(-e.y, e.x);
  return SpriteQuadDC(centreDC, e, sqrt(max(vec2(dot(e, supportDC * e), dot(f, supportDC * f)), 0.0)));
}

// The corner of quad for this vertex, at window depth depthWin; no use for
// point sprites.
vec4 spriteQuadCornerCC(SpriteQuadDC quad, float depthWin) {
  int c = gl_VertexID & 3;
  vec2 s = vec2((c & 1) == 0 ? -1.0 : 1.0, (c & 2) == 0 ? -1.0 : 1.0) * quad.halfSize;
  vec2 pDC = quad.centre + s.x * quad.axis + s.y * vec2(-quad.axis.y, quad.axis.x);
  return vec4(pDC / uViewportDC * 2.0 - 1.0, depthWin, 1.0);
}

// Pixels of rectNDC within the viewport, against those of the quad: the
// quad is drawn where it is the smaller.
bool spriteQuadSmaller(SpriteQuadDC quad, vec4 rectNDC) {
  vec2 sizeDC = (rectNDC.zw - rectNDC.xy) * 0.5 * uViewportDC;
  return 4.0 * quad.halfSize.x * quad.halfSize.y < sizeDC.x * sizeDC.y;
}

// A convex quadrilateral in window pixels, its corners in the order of the
// quad's vertices: the triangles (0 1 2, 2 1 3) share the diagonal 1-2, so
// 0, 1, 3, 2 run around it. Where a glyph's outline is a polygon, such a
// quad can hold it far tighter than any rectangle (a thin diamond fills
// half of its bounding rectangle).
struct SpriteCornersDC {
  vec2 p[4];
};

float spriteCornersArea(SpriteCornersDC q) {
  vec2 a = q.p[3] - q.p[0], b = q.p[1] - q.p[2];
  return 0.5 * abs(a.x * b.y - a.y * b.x);
}

// Moves every side of q out by margin pixels (each corner along the mitre
// of its two sides); false where q is not convex or a corner is too sharp
// for the mitre to stay near it.
bool growSpriteCorners(inout SpriteCornersDC q, float margin) {
  const ivec4 around = ivec4(0, 1, 3, 2);
  vec2 c[4] = vec2[4](q.p[0], q.p[1], q.p[3], q.p[2]);
  vec2 n[4];  // n[i]: the unit normal of side c[i] -> c[i + 1], pointing out
  float turn = 0.0;
  bool convex = true;
  for (int i = 0; i < 4; ++i) {
    vec2 e = c[(i + 1) & 3] - c[i], e2 = c[(i + 2) & 3] - c[(i + 1) & 3];
    float z = e.x * e2.y - e.y * e2.x;
    convex = convex && z != 0.0 && (i == 0 || (z > 0.0) == (turn > 0.0));
    if (i == 0) turn = z;
    n[i] = length(e) > 0.0 ? vec2(e.y, -e.x) / length(e) : vec2(0.0);
  }
  if (!convex) return false;
  for (int i = 0; i < 4; ++i) {
    // Counter-clockwise corners have their outside on the right of each side.
    vec2 n1 = turn > 0.0 ? n[(i + 3) & 3] : -n[(i + 3) & 3], n2 = turn > 0.0 ? n[i] : -n[i];
    float cosine = dot(n1, n2);
    if (!(cosine > -0.999)) return false;
    q.p[around[i]] = c[i] + margin * (n1 + n2) / (1.0 + cosine);
  }
  return true;
}

// The quad corner for this vertex, at window depth depthWin; no use for
// point sprites.
vec4 spriteCornersCC(SpriteCornersDC q, float depthWin) {
  return vec4(q.p[gl_VertexID & 3] / uViewportDC * 2.0 - 1.0, depthWin, 1.0);
}

// Two quads that hold a double pyramid's outline (its square's corners
// 0-3 as (+-e0) + (+-e1) in bit order, its apexes 4 and 5 in cornersNDC):
// the rhombus between the apexes that holds the square, where the square
// stays between them along their axis, and the square itself where it holds
// both apexes; each grown by margin pixels. Returns the smaller that
// exists, false where neither does.
bool pyramidOutlineDC(vec2 cornersNDC[6], float margin, out SpriteCornersDC best) {
  vec2 c[6];
  for (int k = 0; k < 6; ++k) c[k] = (cornersNDC[k] + 1.0) * 0.5 * uViewportDC;
  float bestArea = 1e38;
  // The rhombus: a point at (t, u) along the axis and across it lies in the
  // rhombus of half-diagonals (l, w) where |t| / l + |u| / w <= 1.
  vec2 m = 0.5 * (c[4] + c[5]);
  float l = 0.5 * length(c[5] - c[4]);
  if (l > 0.0) {
    vec2 axis = (c[5] - c[4]) * (0.5 / l), f = vec2(-axis.y, axis.x);
    float w = 0.0;
    bool fits = true;
    for (int k = 0; k < 4; ++k) {
      vec2 d = c[k] - m;
      float t = abs(dot(d, axis)) / l;
      fits = fits && t < 1.0;
      w = max(w, abs(dot(d, f)) / max(1.0 - t, 1e-30));
    }
    SpriteCornersDC r = SpriteCornersDC(vec2[4](c[4], m + w * f, m - w * f, c[5]));
    if (fits && w > 0.0 && growSpriteCorners(r, margin)) {
      best = r;
      bestArea = spriteCornersArea(r);
    }
  }
  // The square: both apexes on the inner side of its four sides.
  SpriteCornersDC sq = SpriteCornersDC(vec2[4](c[0], c[1], c[2], c[3]));
  const ivec4 around = ivec4(0, 1, 3, 2);
  float side = 0.0;
  bool holds = true;
  for (int i = 0; i < 4; ++i) {
    vec2 a = c[around[i]], e = c[around[(i + 1) & 3]] - a;
    for (int k = 4; k < 6; ++k) {
      float z = e.x * (c[k].y - a.y) - e.y * (c[k].x - a.x);
      if (side == 0.0) side = z;
      holds = holds && z * side >= 0.0;
    }
  }
  if (holds && growSpriteCorners(sq, margin) && spriteCornersArea(sq) < bestArea) {
    best = sq;
    bestArea = spriteCornersArea(sq);
  }
  return bestArea < 1e38;
}
