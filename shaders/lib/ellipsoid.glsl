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
// The roots are taken about the centre x0 = b / a, rows shifted by x0 r4:
// b^2 - a c directly loses the digits that b^2 and a c share, for a small
// glyph off-centre up to a pixel; shifted, both terms are of the half-width's
// size and the edges are good to float rounding of x0.
// The outline's terms taken about its centre, shared by the rectangle and
// the oriented outline (lib/sprite.glsl): a = D(r4, r4), the centre x0, the
// rows u1, u2 shifted by x0 r4, and b = D(u_i, r4), zero but for the rounding
// of x0. False where the ellipsoid meets the eye plane.
struct EllipseTerms {
  float a;
  vec2 x0;
  vec4 u1, u2;
  vec2 b;
};

bool ellipseTerms(mat4 pmt, out EllipseTerms e) {
  vec4 r1 = vec4(pmt[0][0], pmt[1][0], pmt[2][0], pmt[3][0]);
  vec4 r2 = vec4(pmt[0][1], pmt[1][1], pmt[2][1], pmt[3][1]);
  vec4 r4 = vec4(pmt[0][3], pmt[1][3], pmt[2][3], pmt[3][3]);
  e.a = formD(r4, r4);
  if (!(e.a < 0.0)) return false;
  e.x0 = vec2(formD(r1, r4), formD(r2, r4)) / e.a;
  e.u1 = r1 - e.x0.x * r4;
  e.u2 = r2 - e.x0.y * r4;
  e.b = vec2(formD(e.u1, r4), formD(e.u2, r4));
  return true;
}

bool ellipsoidRectNDC(mat4 pmt, out vec4 rect) {
  EllipseTerms e;
  if (!ellipseTerms(pmt, e)) return false;
  float a = e.a;
  vec2 x0 = e.x0, b = e.b;
  vec2 s = sqrt(max(b * b - a * vec2(formD(e.u1, e.u1), formD(e.u2, e.u2)), 0.0));
  vec2 lo = x0 + (b + s) / a, hi = x0 + (b - s) / a;  // a < 0, so (b + s)/a is the smaller root
  rect = vec4(min(lo, hi), max(lo, hi));
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

// The farthest view depth on the silhouette contour of the ellipsoid
// centreVC + M x, |x| <= 1, where gcFromVC = M^-1 and depthGC = -(row z of
// M), so that a point's view depth is -centreVC.z + dot(depthGC, x). Every
// ray that hits the ellipsoid crosses the plane of that contour (the eye's
// polar plane; for parallel rays the plane through the centre) between its
// two hits and inside the contour, where view depth is largest on the
// contour itself: no front hit lies behind this depth. False when the eye is
// inside the ellipsoid.
bool silhouetteFarVC(mat3 gcFromVC, vec3 depthGC, vec3 centreVC, out float farVC) {
  farVC = -centreVC.z;
  float ww = dot(depthGC, depthGC);
  if (uOrtho == 1) {
    vec3 e = normalize(gcFromVC * vec3(0.0, 0.0, -1.0));
    float we = dot(depthGC, e);
    farVC += sqrt(max(ww - we * we, 0.0));
    return true;
  }
  // The eye in parameter space; the contour is the circle x.e = 1, |x| = 1:
  // centre e / |e|^2, radius sqrt(1 - 1 / |e|^2).
  vec3 e = -(gcFromVC * centreVC);
  float ee = dot(e, e);
  if (!(ee > 1.0)) return false;
  float we = dot(depthGC, e);
  farVC += we / ee + sqrt(1.0 - 1.0 / ee) * sqrt(max(ww - we * we / ee, 0.0));
  return true;
}
