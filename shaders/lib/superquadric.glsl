// Superquadric glyphs: shape (the GLSL twin of src/tensor/superquadric.cpp,
// after Teem's tenGlyphGen), implicit function, and the box-seeded Newton
// march's gauge; the march itself is lib/superquadric_march.glsl.
// Requires lib/ellipsoid.glsl (kMinAxisRatio, unitSphereRoots). In the
// GLSL/C++ subset (lib/glsl_cpp.h).

const float kMinShapeExponent = 2e-3f;  // mirrors tg::tensor::kMinShapeExponent

float sphericalTriangleArea(vec3 a, vec3 b, vec3 c) {
  return 2.0f * atan(abs(dot(a, cross(b, c))), 1.0f + dot(a, b) + dot(b, c) + dot(c, a));
}

vec3 sphericalBarycentric(vec3 p0, vec3 p1, vec3 p2, vec3 v) {
  vec3 w = vec3(sphericalTriangleArea(v, p1, p2), sphericalTriangleArea(p0, v, p2), sphericalTriangleArea(p0, p1, v));
  return w / (w.x + w.y + w.z);
}

// (a, b, c) in xyz and the eigenvector index GC z follows in w.
vec4 kindlmann2004(vec3 l, float gamma, bool mirrored) {
  float tr = l.x + l.y + l.z;
  float cl = min(0.99f, (l.x - l.y) / tr), cp = min(0.99f, 2.0f * (l.y - l.z) / tr);
  bool linear = cl > cp;
  vec2 ab = pow(1.0f - (linear ? vec2(cp, cl) : vec2(cl, cp)), vec2(gamma));
  return vec4(ab, ab.y, linear != mirrored ? 0.0f : 2.0f);
}

// The spherical triangle of Schultz and Kindlmann's shape space that holds l,
// its corners' shapes and the symmetry axis, chosen first so that the
// barycentric weights (three atan each) are computed once: every branch of a
// selection runs on a SIMD renderer such as llvmpipe.
vec4 schultz2010(vec3 l) {
  const float r2 = 0.70710678f, r3 = 0.57735027f;
  const vec3 B = vec3(1, 0, 0), C = vec3(r2, r2, 0), D = vec3(r3, -r3, -r3), E = vec3(r2, 0, -r2),
             F = vec3(r3, r3, -r3), G = vec3(0, -r2, -r2), H = vec3(0, 0, -1);
  const vec3 funk = vec3(0, 4, 2), thrn = vec3(1, 4, 4), octa = vec3(0, 2, 2), cone = vec3(1, 2, 2);
  vec3 n = normalize(l / max(abs(l.x), abs(l.z)));  // pre-scaled: |l|^2 may overflow float
  vec3 p0, p1, p2;
  mat3 corners;
  float axis;
  if (l.y >= -l.z) {
    p0 = B; p1 = F; p2 = C; corners = mat3(octa, thrn, cone); axis = 2.0f;
  } else if (l.x >= -l.z) {
    if (l.y >= 0.0f) {
      p0 = B; p1 = E; p2 = F; corners = mat3(octa, funk, thrn); axis = 2.0f;
    } else {
      p0 = B; p1 = D; p2 = E; corners = mat3(cone, thrn, funk); axis = 0.0f;
    }
  } else if (l.x < -l.y) {
    p0 = D; p1 = G; p2 = H; corners = mat3(thrn, cone, octa); axis = 0.0f;
  } else if (l.y < 0.0f) {
    p0 = E; p1 = D; p2 = H; corners = mat3(funk, thrn, octa); axis = 0.0f;
  } else {
    p0 = F; p1 = E; p2 = H; corners = mat3(thrn, funk, cone); axis = 2.0f;
  }
  return vec4(corners * sphericalBarycentric(p0, p1, p2, n), axis);
}

vec4 superquadricShape(vec3 l, float gamma) {
  if (l.x == 0.0f && l.z == 0.0f) return vec4(1.0f, 1.0f, 1.0f, 2.0f);
  // Definite either way: one Kindlmann shape, of l or of the mirrored -l.zyx.
  bool negative = !(l.z > 0.0f);
  vec4 s = l.z > 0.0f || l.x < 0.0f ? kindlmann2004(negative ? -vec3(l.z, l.y, l.x) : l, gamma, negative) : schultz2010(l);
  return vec4(max(vec3(s), vec3(kMinShapeExponent)), s.w);
}

// Every shape lies within this distance of the GC origin, so within the
// glyph's ellipsoid grown by it: |(x, y)| <= 2^max(0, (1 - a)/2) s (Hoelder on
// the 2/a-norm), and s^2 + z^2 <= 2^(1 - min(b, c, 1)) where
// s^(2/b) + |z|^(2/c) <= 1; never beyond the cube's corner. 1 for ellipsoids.
float superquadricReach(vec3 shape) {
  float m = min(min(shape.y, shape.z), 1.0f);
  return min(exp2(0.5f * (max(0.0f, 1.0f - shape.x) + 1.0f - m)), sqrt(3.0f));
}

// g(p) = (s^(2/b) + |z|^(2/c))^(b/2), s = (|x|^(2/a) + |y|^(2/a))^(a/2), and
// its gradient. Powers are taken of ratios in [0, 1] or in log2, so exponents
// up to 1000 neither overflow nor divide by zero.
float superquadricGauge(vec3 shape, vec3 p, TG_OUT(vec3) grad) {
  vec3 ap = abs(p);
  float m = max(ap.x, ap.y);
  float sxy = 0.0f;
  vec2 r = vec2(0.0f);
  if (m > 0.0f) {
    vec2 q = max(vec2(ap) / m, vec2(1e-30f));  // log2(0) is undefined in GLSL
    vec2 pq = exp2(2.0f / shape.x * log2(q));
    float sum = pq.x + pq.y;
    sxy = m * exp2(shape.x / 2.0f * log2(sum));
    r = exp2((2.0f / shape.x - 1.0f) * log2(q)) / (sum * m);
  }
  grad = vec3(0.0f);
  if (sxy == 0.0f && ap.z == 0.0f) return 0.0f;
  float lu = sxy > 0.0f ? 2.0f / shape.y * log2(sxy) : -1e30f;
  float lw = ap.z > 0.0f ? 2.0f / shape.z * log2(ap.z) : -1e30f;
  float hi = max(lu, lw), e = exp2(min(lu, lw) - hi);
  float g = exp2(shape.y / 2.0f * (hi + log2(1.0f + e)));
  float wu = lu >= lw ? 1.0f / (1.0f + e) : e / (1.0f + e);
  float dz = ap.z > 0.0f ? shape.y / shape.z * (1.0f - wu) / ap.z : 0.0f;
  grad = g * sign(p) * vec3(wu * r, dz);
  return g;
}

// The gauge alone, as the blobs' sums take it at every sample: s taken
// about the larger of |x| and |y|, m, as s = m (1 + t^(2/a))^(a/2) with
// t = min / m in [0, 1], whose power of 1 costs nothing, and kept in log2:
// eight log2 and exp2 a call against superquadricGauge's thirteen, equal to
// it within float rounding (test_superquadric_math.cpp).
float superquadricGaugeValue(vec3 shape, vec3 p) {
  vec3 ap = abs(p);
  float m = max(ap.x, ap.y);
  if (m == 0.0f && ap.z == 0.0f) return 0.0f;
  float lu = -1e30f;
  if (m > 0.0f) {
    float t = max(min(ap.x, ap.y) / m, 1e-30f);  // log2(0) is undefined in GLSL
    lu = 2.0f / shape.y * (log2(m) + shape.x / 2.0f * log2(1.0f + exp2(2.0f / shape.x * log2(t))));
  }
  float lw = ap.z > 0.0f ? 2.0f / shape.z * log2(ap.z) : -1e30f;
  float hi = max(lu, lw);
  return exp2(shape.y / 2.0f * (hi + log2(1.0f + exp2(min(lu, lw) - hi))));
}
