// Teem's cylinder and box glyphs (tenGlyphGen, teem/src/ten/glyph.c): the
// bi-unit solid of limnObjectCylinderAdd / limnObjectCubeAdd (echo's
// echoTypeCylinder / echoTypeCube for `tend glyph -rt`), scaled by
// |eigenvalue| per eigenvector, so a mixed-sign tensor keeps its size and
// `--color sign` shows the signs. Exact ray intersections in GC, where the
// glyph is the unit cylinder x^2 + y^2 <= 1, |z| <= 1 (z: the cylinder's
// axis) or the cube [-1, 1]^3: a quadric and two cap planes (Sigg et al.
// 2006), or three slabs.
// In the GLSL/C++ subset (lib/glsl_cpp.h): the raster path's prism programs
// and the CPU glyph path run these same functions. Requires lib/camera.glsl,
// lib/glyph_record_type.glsl, lib/ellipsoid.glsl, lib/glyph_size.glsl and
// lib/selection.glsl. `cylinder` chooses the solid: the prism programs pass
// their TG_CYLINDER option as a constant.

// The eigenvector (0 major, 2 minor) Teem's cylinder runs along: Teem's
// superquadric symmetry axis. Positive tensors: e0 when Westin's cl1 > cp1,
// i.e. l0 - l1 > 2 (l1 - l2), else e2 (a disc); negative ones the same on
// |l| (mirrored); mixed signs or zeros (Schultz & Kindlmann 2010's zones)
// reduce to the eigenvector whose sign is the odd one out: e2 when l1 >= 0.
int cylinderAxis(vec3 l) {
  if (l.z > 0.0f) return l.x - l.y > 2.0f * (l.y - l.z) ? 0 : 2;
  if (l.x < 0.0f) return l.y - l.z > 2.0f * (l.x - l.y) ? 2 : 0;
  return l.y >= 0.0f ? 2 : 0;
}

// The ray o + t d against the slab |p_k| <= 1: [t0, t1], empty where t0 > t1.
vec2 slabSpan(float o, float d) {
  if (d == 0.0f) return abs(o) <= 1.0f ? vec2(-1e30f, 1e30f) : vec2(1.0f, -1.0f);
  float a = (-1.0f - o) / d, b = (1.0f - o) / d;
  return vec2(min(a, b), max(a, b));
}

// The ray's span inside the glyph and the GC normals where it enters and
// leaves. False on a miss.
bool cylinderSpan(vec3 o, vec3 d, TG_OUT(vec2) span, TG_OUT(vec3) nIn, TG_OUT(vec3) nOut) {
  vec2 side = vec2(-1e30f, 1e30f);
  vec2 oxy = vec2(o.x, o.y), dxy = vec2(d.x, d.y);
  float dd = dot(dxy, dxy);
  if (dd > 0.0f) {
    // From the closest approach to the axis, as unitSphereRoots: no cancellation.
    float tm = -dot(oxy, dxy) / dd;
    vec2 q = oxy + tm * dxy;
    float h = 1.0f - dot(q, q);
    if (h < 0.0f) return false;
    float s = sqrt(h / dd);
    side = vec2(tm - s, tm + s);
  } else if (dot(oxy, oxy) > 1.0f) {
    return false;
  }
  vec2 caps = slabSpan(o.z, d.z);
  span = vec2(max(side.x, caps.x), min(side.y, caps.y));
  if (!(span.x <= span.y)) return false;
  vec3 pIn = o + span.x * d, pOut = o + span.y * d;
  nIn = caps.x > side.x ? vec3(0.0f, 0.0f, -sign(d.z)) : vec3(pIn.x, pIn.y, 0.0f);
  nOut = caps.y < side.y ? vec3(0.0f, 0.0f, sign(d.z)) : vec3(pOut.x, pOut.y, 0.0f);
  return true;
}

bool boxSpan(vec3 o, vec3 d, TG_OUT(vec2) span, TG_OUT(vec3) nIn, TG_OUT(vec3) nOut) {
  vec2 s0 = slabSpan(o.x, d.x), s1 = slabSpan(o.y, d.y), s2 = slabSpan(o.z, d.z);
  span = vec2(max(s0.x, max(s1.x, s2.x)), min(s0.y, min(s1.y, s2.y)));
  if (!(span.x <= span.y)) return false;
  // Flat faces: the normal of the slab that set the entry (exit).
  int kIn = span.x == s0.x ? 0 : span.x == s1.x ? 1 : 2;
  int kOut = span.y == s0.y ? 0 : span.y == s1.y ? 1 : 2;
  nIn = vec3(0.0f);
  nOut = vec3(0.0f);
  nIn[kIn] = -sign(d[kIn]);
  nOut[kOut] = sign(d[kOut]);
  return true;
}

// A prism glyph as the sprite stage (prism.vert) and the CPU glyph path set
// it up: the selection, the culls that need no neighbour, and its tight
// screen rectangle. A box's is that of its 8 corners; a cylinder's the union
// of its two cap discs' (each Sigg et al. 2006 eq. 5 with a flat parameter
// axis, their per-cap bounding boxes, §3.2): the projection of a convex hull
// is the hull of the projections.
struct PrismSprite {
  vec3 centreVC;
  mat3 rotWC;     // eigenvectors in WC
  ivec3 src;      // GC axis k is eigenvector src[k]: a cyclic permutation (the cylinder's axis on z)
  mat3 gcFromVC;  // rows: GC axes in VC over their lengths
  float nearVC;   // no hit is nearer: the sprite's depth
  vec4 rectNDC;   // (xmin, ymin, xmax, ymax), grown by a pixel, within the viewport
};

// The glyph's frame, what a cast needs: centreVC, rotWC, src, gcFromVC;
// its GC axes in VC times their semi-axes in e0..e2.
void prismFrame(GlyphRecord g, vec3 axes, bool cylinder, TG_OUT(PrismSprite) s, TG_OUT(vec3) e0, TG_OUT(vec3) e1,
                TG_OUT(vec3) e2) {
  s.rotWC = quatToMat3(g.frameWC);
  mat3 rotVC = mat3(uViewWCVC) * s.rotWC;
  s.centreVC = vec3(uViewWCVC * vec4(vec3(g.posWC_fa), 1.0f));
  // GC z on the cylinder's axis; a cyclic permutation keeps GC right-handed.
  int ax = cylinder ? cylinderAxis(vec3(g.eigenvalues_id)) : 2;
  s.src = ivec3((ax + 1) % 3, (ax + 2) % 3, ax);
  e0 = rotVC[s.src.x] * axes[s.src.x];
  e1 = rotVC[s.src.y] * axes[s.src.y];
  e2 = rotVC[s.src.z] * axes[s.src.z];
  s.gcFromVC = transpose(mat3(e0 / dot(e0, e0), e1 / dot(e1, e1), e2 / dot(e2, e2)));
}

bool prismSprite(GlyphRecord g, bool cylinder, TG_OUT(PrismSprite) s) {
  if (!glyphSelected(g.posWC_fa)) return false;
  vec3 axes = glyphAxes(vec3(g.eigenvalues_id));
  if (!(max(axes.x, max(axes.y, axes.z)) > 0.0f)) return false;
  vec3 e0, e1, e2;
  prismFrame(g, axes, cylinder, s, e0, e1, e2);

  vec4 rect = vec4(1e38f, 1e38f, -1e38f, -1e38f);
  bool full = false;
  float nearest = 1e38f, farthest = -1e38f;
  if (cylinder) {
    for (int k = 0; k < 2; ++k) {
      vec3 capVC = s.centreVC + (k == 0 ? -e2 : e2);
      // The disc's depth extent along the view axis is exact: |(e0.z, e1.z)|.
      float reach = length(vec2(e0.z, e1.z));
      nearest = min(nearest, -capVC.z - reach);
      farthest = max(farthest, -capVC.z + reach);
      mat4 pmt = uProjVCCC * mat4(vec4(e0, 0.0f), vec4(e1, 0.0f), vec4(0.0f), vec4(capVC, 1.0f));
      vec4 capRect;
      // A cap meeting or behind the eye plane (w <= 0 at its centre) has no finite rectangle.
      if (!ellipsoidRectNDC(pmt, capRect) || !(pmt[3][3] > 0.0f)) full = true;
      else rect = vec4(min(rect.x, capRect.x), min(rect.y, capRect.y), max(rect.z, capRect.z), max(rect.w, capRect.w));
    }
  } else {
    for (int k = 0; k < 8; ++k) {
      vec3 c = s.centreVC + ((k & 1) == 0 ? -e0 : e0) + ((k & 2) == 0 ? -e1 : e1) + ((k & 4) == 0 ? -e2 : e2);
      nearest = min(nearest, -c.z);
      farthest = max(farthest, -c.z);
      vec4 cc = uProjVCCC * vec4(c, 1.0f);
      if (cc.w <= 0.0f) full = true;
      vec2 ndc = vec2(cc) / cc.w;
      rect = vec4(min(rect.x, ndc.x), min(rect.y, ndc.y), max(rect.z, ndc.x), max(rect.w, ndc.y));
    }
  }
  if (farthest < uNearVC || (uOrtho == 1 && nearest > uFarVC)) return false;
  if (full) rect = vec4(-1.0f, -1.0f, 1.0f, 1.0f);
  // One pixel of margin so that pixel centres on the exact edge are kept.
  vec2 px = 2.0f / uViewportDC;
  s.rectNDC = clamp(rect + vec4(-px, px), -1.0f, 1.0f);
  if (s.rectNDC.x >= s.rectNDC.z || s.rectNDC.y >= s.rectNDC.w) return false;
  s.nearVC = max(nearest, uNearVC);
  return true;
}

// The ray through window point fragDC against a prism set up as `centreVC`
// and `gcFromVC`: the first surface at or beyond the near plane (from
// inside, the far wall), its view depth, GC point and GC normal. False on a
// miss or outside the depth range.
bool castPrism(vec2 fragDC, vec3 centreVC, mat3 gcFromVC, bool cylinder, TG_OUT(float) depthVC, TG_OUT(vec3) pGC,
               TG_OUT(vec3) nGC) {
  vec3 originVC, dirVC;
  rayThroughFragment(fragDC, originVC, dirVC);
  // Restart at the closest approach to the centre, as for ellipsoids: GC
  // coordinates stay O(1) on every ray that can hit.
  float tc = dot(centreVC - originVC, dirVC) / dot(dirVC, dirVC);
  vec3 o = gcFromVC * (originVC + tc * dirVC - centreVC);
  vec3 d = gcFromVC * dirVC;
  vec2 span;
  vec3 nIn, nOut;
  if (cylinder ? !cylinderSpan(o, d, span, nIn, nOut) : !boxSpan(o, d, span, nIn, nOut)) return false;
  bool entry = tc + span.x >= uNearVC;
  float t = entry ? span.x : span.y;
  depthVC = tc + t;
  if (!(depthVC >= uNearVC) || (uOrtho == 1 && depthVC > uFarVC)) return false;
  pGC = o + t * d;
  nGC = entry ? nIn : nOut;
  return true;
}

// A GC normal as a unit WC normal.
vec3 prismNormalWC(mat3 gcFromVC, vec3 nGC) {
  vec3 nVC = transpose(gcFromVC) * nGC;  // inverse transpose of GC -> VC
  return normalize(transpose(mat3(uViewWCVC)) * nVC);
}
