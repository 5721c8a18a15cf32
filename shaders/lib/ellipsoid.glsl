// Ellipsoid maths after Sigg et al. 2006, shared by every stage that needs it.
// Requires lib/camera.glsl. In the GLSL/C++ subset (lib/glsl_cpp.h).
// C++ includes it as shaders/lib/glsl_cpp.h first (render/glsl_cpp.h).
#ifndef TG_GLSL_CPP_H
#include "lib/glsl_cpp.h"
#endif

// Mirrors tg::tensor::kMinAxisRatio: the thinnest axis relative to the longest.
const float kMinAxisRatio = 1e-7f;

vec3 ellipsoidAxes(vec3 eigenvalues, float scale) {
  vec3 a = abs(eigenvalues) * scale;
  return max(a, vec3(kMinAxisRatio * max(a.x, max(a.y, a.z))));
}

// Bilinear form with D = diag(1, 1, 1, -1): the unit sphere in homogeneous
// parameter coordinates.
float formD(vec4 u, vec4 v) { return dot(vec3(u), vec3(v)) - u.w * v.w; }

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

// From pmt's rows 1, 2 and 4 (x, y and w).
bool ellipseTermsOfRows(vec4 r1, vec4 r2, vec4 r4, TG_OUT(EllipseTerms) e) {
  e.a = formD(r4, r4);
  if (!(e.a < 0.0f)) return false;
  e.x0 = vec2(formD(r1, r4), formD(r2, r4)) / e.a;
  e.u1 = r1 - e.x0.x * r4;
  e.u2 = r2 - e.x0.y * r4;
  e.b = vec2(formD(e.u1, r4), formD(e.u2, r4));
  return true;
}

bool ellipseTerms(mat4 pmt, TG_OUT(EllipseTerms) e) {
  return ellipseTermsOfRows(vec4(pmt[0][0], pmt[1][0], pmt[2][0], pmt[3][0]),
                            vec4(pmt[0][1], pmt[1][1], pmt[2][1], pmt[3][1]),
                            vec4(pmt[0][3], pmt[1][3], pmt[2][3], pmt[3][3]), e);
}

void ellipseRectNDC(EllipseTerms e, TG_OUT(vec4) rect) {
  float a = e.a;
  vec2 x0 = e.x0, b = e.b;
  vec2 s = sqrt(max(b * b - a * vec2(formD(e.u1, e.u1), formD(e.u2, e.u2)), 0.0f));
  vec2 lo = x0 + (b + s) / a, hi = x0 + (b - s) / a;  // a < 0, so (b + s)/a is the smaller root
  rect = vec4(min(lo, hi), max(lo, hi));
}

bool ellipsoidRectNDC(mat4 pmt, TG_OUT(vec4) rect) {
  EllipseTerms e;
  if (!ellipseTerms(pmt, e)) return false;
  ellipseRectNDC(e, rect);
  return true;
}

// The same for the ellipsoid centreVC + m x, |x| <= 1, with pmt = uProjVCCC *
// [m, centreVC; 0, 1] taken row by row: a projection row p gives (m^T p.xyz,
// p . (centreVC, 1)), 12 multiply-adds instead of the matrix product's 64,
// for the set-up and the culls that run on every glyph.
bool ellipsoidFrameRectNDC(mat3 m, vec3 centreVC, TG_OUT(vec4) rect) {
  vec4 p1 = vec4(uProjVCCC[0][0], uProjVCCC[1][0], uProjVCCC[2][0], uProjVCCC[3][0]);
  vec4 p2 = vec4(uProjVCCC[0][1], uProjVCCC[1][1], uProjVCCC[2][1], uProjVCCC[3][1]);
  vec4 p4 = vec4(uProjVCCC[0][3], uProjVCCC[1][3], uProjVCCC[2][3], uProjVCCC[3][3]);
  EllipseTerms e;
  if (!ellipseTermsOfRows(vec4(vec3(p1) * m, dot(vec3(p1), centreVC) + p1.w),
                          vec4(vec3(p2) * m, dot(vec3(p2), centreVC) + p2.w),
                          vec4(vec3(p4) * m, dot(vec3(p4), centreVC) + p4.w), e))
    return false;
  ellipseRectNDC(e, rect);
  return true;
}

// Sigg et al. eq. (7), with the ray parametrised by view depth t instead of
// window depth z_w. z_w is a projective function of t, so the roots are the
// same points; t keeps float precision that z_w compresses away with distance.
// Roots of |o + t d|^2 = 1 from the closest approach to the centre, so that
// neither suffers cancellation.
bool unitSphereRoots(vec3 o, vec3 d, TG_OUT(float) t0, TG_OUT(float) t1) {
  float dd = dot(d, d);
  float tc = -dot(o, d) / dd;
  vec3 q = o + tc * d;
  float h = 1.0f - dot(q, q);
  if (h < 0.0f) return false;
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
bool silhouetteFarVC(mat3 gcFromVC, vec3 depthGC, vec3 centreVC, TG_OUT(float) farVC) {
  farVC = -centreVC.z;
  float ww = dot(depthGC, depthGC);
  if (uOrtho == 1) {
    vec3 e = normalize(gcFromVC * vec3(0.0f, 0.0f, -1.0f));
    float we = dot(depthGC, e);
    farVC += sqrt(max(ww - we * we, 0.0f));
    return true;
  }
  // The eye in parameter space; the contour is the circle x.e = 1, |x| = 1:
  // centre e / |e|^2, radius sqrt(1 - 1 / |e|^2).
  vec3 e = -(gcFromVC * centreVC);
  float ee = dot(e, e);
  if (!(ee > 1.0f)) return false;
  float we = dot(depthGC, e);
  farVC += we / ee + sqrt(1.0f - 1.0f / ee) * sqrt(max(ww - we * we / ee, 0.0f));
  return true;
}

// The parameter -> view transform's parts for a glyph of frame rotVC (its
// axes in VC) and semi-axes `axes`: gcFromVC = M^-1 for M = rotVC diag(axes),
// and T of Sigg et al. eq. (2) in VC, for ellipsoidRectNDC(uProjVCCC * T).
mat3 ellipsoidGcFromVC(mat3 rotVC, vec3 axes) {
  return transpose(mat3(rotVC[0] / axes.x, rotVC[1] / axes.y, rotVC[2] / axes.z));
}

mat4 ellipsoidTVC(mat3 rotVC, vec3 axes, vec3 centreVC) {
  return mat4(vec4(rotVC[0] * axes.x, 0.0f), vec4(rotVC[1] * axes.y, 0.0f), vec4(rotVC[2] * axes.z, 0.0f),
              vec4(centreVC, 1.0f));
}

// The ray through window position fragDC against the ellipsoid centreVC + M x,
// |x| <= 1 (gcFromVC = M^-1): its first surface at or beyond the near plane
// (from inside, the far wall), as view depth and the GC point, which is also
// the GC normal. False where the ray misses or the hit lies outside the depth
// range. The ray restarts at its closest approach to the centre: on every
// ray that can hit, GC coordinates are then O(1) even for 1e6:1 glyphs far away.
bool castEllipsoid(vec2 fragDC, vec3 centreVC, mat3 gcFromVC, TG_OUT(float) depthVC, TG_OUT(vec3) nGC) {
  vec3 originVC, dirVC;
  rayThroughFragment(fragDC, originVC, dirVC);
  float tc = dot(centreVC - originVC, dirVC) / dot(dirVC, dirVC);
  vec3 o = gcFromVC * (originVC + tc * dirVC - centreVC);
  vec3 d = gcFromVC * dirVC;
  float t0, t1;
  if (!unitSphereRoots(o, d, t0, t1)) return false;
  float t = tc + t0 >= uNearVC ? t0 : t1;
  depthVC = tc + t;
  if (!(depthVC >= uNearVC) || (uOrtho == 1 && depthVC > uFarVC)) return false;
  nGC = o + t * d;
  return true;
}

// The unit WC normal at GC point nGC: the inverse transpose of GC -> VC, then VC -> WC.
vec3 ellipsoidNormalWC(mat3 gcFromVC, vec3 nGC) {
  return normalize(transpose(mat3(uViewWCVC)) * (transpose(gcFromVC) * nGC));
}
