// Teem's cylinder and box glyphs (tenGlyphGen, teem/src/ten/glyph.c): the
// bi-unit solid of limnObjectCylinderAdd / limnObjectCubeAdd (echo's
// echoTypeCylinder / echoTypeCube for `tend glyph -rt`), scaled by
// |eigenvalue| per eigenvector, so a mixed-sign tensor keeps its size and
// `--color sign` shows the signs. Exact ray intersections in GC, where the
// glyph is the unit cylinder x^2 + y^2 <= 1, |z| <= 1 (z: the cylinder's
// axis) or the cube [-1, 1]^3: a quadric and two cap planes (Sigg et al.
// 2006), or three slabs.

// The eigenvector (0 major, 2 minor) Teem's cylinder runs along: Teem's
// superquadric symmetry axis. Positive tensors: e0 when Westin's cl1 > cp1,
// i.e. l0 - l1 > 2 (l1 - l2), else e2 (a disc); negative ones the same on
// |l| (mirrored); mixed signs or zeros (Schultz & Kindlmann 2010's zones)
// reduce to the eigenvector whose sign is the odd one out: e2 when l1 >= 0.
int cylinderAxis(vec3 l) {
  if (l.z > 0.0) return l.x - l.y > 2.0 * (l.y - l.z) ? 0 : 2;
  if (l.x < 0.0) return l.y - l.z > 2.0 * (l.x - l.y) ? 2 : 0;
  return l.y >= 0.0 ? 2 : 0;
}

// The ray o + t d against the slab |p_k| <= 1: [t0, t1], empty where t0 > t1.
vec2 slabSpan(float o, float d) {
  if (d == 0.0) return abs(o) <= 1.0 ? vec2(-1e30, 1e30) : vec2(1.0, -1.0);
  float a = (-1.0 - o) / d, b = (1.0 - o) / d;
  return vec2(min(a, b), max(a, b));
}

// The ray's span inside the glyph and the GC normals where it enters and
// leaves. False on a miss.
bool cylinderSpan(vec3 o, vec3 d, out vec2 span, out vec3 nIn, out vec3 nOut) {
  vec2 side = vec2(-1e30, 1e30);
  float dd = dot(d.xy, d.xy);
  if (dd > 0.0) {
    // From the closest approach to the axis, as unitSphereRoots: no cancellation.
    float tm = -dot(o.xy, d.xy) / dd;
    vec2 q = o.xy + tm * d.xy;
    float h = 1.0 - dot(q, q);
    if (h < 0.0) return false;
    float s = sqrt(h / dd);
    side = vec2(tm - s, tm + s);
  } else if (dot(o.xy, o.xy) > 1.0) {
    return false;
  }
  vec2 caps = slabSpan(o.z, d.z);
  span = vec2(max(side.x, caps.x), min(side.y, caps.y));
  if (!(span.x <= span.y)) return false;
  vec3 pIn = o + span.x * d, pOut = o + span.y * d;
  nIn = caps.x > side.x ? vec3(0.0, 0.0, -sign(d.z)) : vec3(pIn.xy, 0.0);
  nOut = caps.y < side.y ? vec3(0.0, 0.0, sign(d.z)) : vec3(pOut.xy, 0.0);
  return true;
}

bool boxSpan(vec3 o, vec3 d, out vec2 span, out vec3 nIn, out vec3 nOut) {
  vec2 s0 = slabSpan(o.x, d.x), s1 = slabSpan(o.y, d.y), s2 = slabSpan(o.z, d.z);
  span = vec2(max(s0.x, max(s1.x, s2.x)), min(s0.y, min(s1.y, s2.y)));
  if (!(span.x <= span.y)) return false;
  // Flat faces: the normal of the slab that set the entry (exit).
  int kIn = span.x == s0.x ? 0 : span.x == s1.x ? 1 : 2;
  int kOut = span.y == s0.y ? 0 : span.y == s1.y ? 1 : 2;
  nIn = vec3(0.0);
  nOut = vec3(0.0);
  nIn[kIn] = -sign(d[kIn]);
  nOut[kOut] = sign(d[kOut]);
  return true;
}
