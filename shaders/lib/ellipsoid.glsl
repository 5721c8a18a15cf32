// Ellipsoid maths after Sigg et al. 2006, shared by every stage that needs it.
// Requires lib/camera.glsl.

// Mirrors tg::tensor::kMinAxisRatio: the thinnest axis relative to the longest.
const float kMinAxisRatio = 1e-7;

vec3 ellipsoidAxes(vec3 eigenvalues, float scale) {
  vec3 a = abs(eigenvalues) * scale;
  return max(a, vec3(kMinAxisRatio * max(a.x, max(a.y, a.z))));
}

// Bilinear form with D = diag(1, 1, 1, -1): the unit sphere in homogeneous
// parameter coordinates.
float formD(vec4 u, vec4 v) { return dot(u.xyz, v.xyz) - u.w * v.w; }

// Sigg et al. eq. (5): tight NDC rectangle (xmin, ymin, xmax, ymax) of the
// ellipsoid whose parameter->clip transform is pmt. Returns false when the
// ellipsoid meets the eye plane (w = 0): then no finite rectangle exists.
bool ellipsoidRectNDC(mat4 pmt, out vec4 rect) {
  vec4 r1 = vec4(pmt[0][0], pmt[1][0], pmt[2][0], pmt[3][0]);
  vec4 r2 = vec4(pmt[0][1], pmt[1][1], pmt[2][1], pmt[3][1]);
  vec4 r4 = vec4(pmt[0][3], pmt[1][3], pmt[2][3], pmt[3][3]);
  float a = formD(r4, r4);
  if (!(a < 0.0)) return false;
  float bx = formD(r1, r4), cx = formD(r1, r1);
  float by = formD(r2, r4), cy = formD(r2, r2);
  vec2 b = vec2(bx, by);
  vec2 s = sqrt(max(b * b - a * vec2(cx, cy), 0.0));
  vec2 lo = (b + s) / a, hi = (b - s) / a;  // a < 0, so (b + s)/a is the smaller root
  rect = vec4(min(lo, hi), max(lo, hi));
  return true;
}

// As above, with a bound on each edge's rounding error: s^2 = b^2 - a c loses
// the digits that b^2 and a c share (a small glyph far off-centre), and an
// error e in s^2 moves the edges by e / (2 s |a|).
bool ellipsoidRectNDC(mat4 pmt, out vec4 rect, out vec2 errNDC) {
  errNDC = vec2(0.0);
  if (!ellipsoidRectNDC(pmt, rect)) return false;
  vec4 r1 = vec4(pmt[0][0], pmt[1][0], pmt[2][0], pmt[3][0]);
  vec4 r2 = vec4(pmt[0][1], pmt[1][1], pmt[2][1], pmt[3][1]);
  vec4 r4 = vec4(pmt[0][3], pmt[1][3], pmt[2][3], pmt[3][3]);
  float a = formD(r4, r4);
  vec2 b = vec2(formD(r1, r4), formD(r2, r4));
  vec2 ac = a * vec2(formD(r1, r1), formD(r2, r2));
  vec2 s2 = b * b - ac;
  // 8 ulp of the larger term covers the products, the sums and the sqrt.
  errNDC = 8.0 * 1.2e-7 * (b * b + abs(ac)) / (2.0 * sqrt(max(s2, 1e-37)) * abs(a)) + 1.2e-7 * (rect.zw - rect.xy);
  return true;
}

// Sigg et al. eq. (7), with the ray parametrised by view depth t instead of
// window depth z_w. z_w is a projective function of t, so the roots are the
// same points; t keeps float precision that z_w compresses away with distance.
// Roots of |o + t d|^2 = 1 from the closest approach to the centre, so that
// neither suffers cancellation.
bool unitSphereRoots(vec3 o, vec3 d, out float t0, out float t1) {
  float dd = dot(d, d);
  float tc = -dot(o, d) / dd;
  vec3 q = o + tc * d;
  float h = 1.0 - dot(q, q);
  if (h < 0.0) return false;
  float s = sqrt(h / dd);
  t0 = tc - s;
  t1 = tc + s;
  return true;
}
