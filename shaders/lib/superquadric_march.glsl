// The box-seeded Newton march of Hlawitschka et al. with a kept bracket
// (Blinn 1982, §3.3) through a superquadric's gauge (lib/superquadric.glsl).
//
// Written for llvmpipe's cost model (Mesa 22.3 gallivm): a fragment shader
// runs 8 fragments in lock-step and executes both sides of every if, masked;
// discard only masks; a loop runs its body at least once and repeats while
// any lane is still in it. So every gauge call written into the march costs
// each fragment in full whether reached or not, and only loop iterations are
// ever skipped. The march is therefore one loop with one gauge call, and
// each iteration does one phase's step: the entry's, a grid sample's, a
// bisection step's, a Newton step's or the hit's final gradient.
//
// Variants, each for a glyph group whose shapes it is exact for:
//  TG_MARCH_CONVEX: definite tensors' Kindlmann shapes (a, b, b), a, b <= 1,
//    which superquadricConvex always holds: no grid search.
//  TG_MARCH_MIXED: Schultz-Kindlmann shapes (b, c >= 2): rays that miss
//    the double pyramid max(|x|, |y|) + |z| <= 1 holding them never march.
//
// In the GLSL/C++ subset (lib/glsl_cpp.h); C++ includes it once per variant
// (render/glsl_cpp.h), with the variant's macro defined.
#ifndef __cplusplus
#pragma tg option TG_MARCH_CONVEX
#pragma tg option TG_MARCH_MIXED
#endif

// Convex along every line when g is a norm (2/a, 2/b >= 1, c = b); it then
// also contains the unit sphere when a, b <= 1.
bool superquadricConvex(vec3 shape) { return shape.x <= 2.0f && shape.y <= 2.0f && shape.z == shape.y; }

struct MarchResult {
  bool hit;
  float s;      // arc length along the unit GC direction
  vec3 gradGC;
  int iterations;
  int gaugeCalls;  // passes of the loop, for iteration statistics
};

// Entry and exit of the ray o + s dir through the cube [-1, 1]^3 that holds
// every shape (slabs); empty where x > y.
vec2 unitCubeSpan(vec3 o, vec3 dir) {
  vec3 inv = 1.0f / dir;
  vec3 ta = (-1.0f - o) * inv, tb = (1.0f - o) * inv;
  return vec2(max(max(min(ta.x, tb.x), min(ta.y, tb.y)), min(ta.z, tb.z)),
              min(min(max(ta.x, tb.x), max(ta.y, tb.y)), max(ta.z, tb.z)));
}

// The span of the line o + s dir in max(|x|, |y|) + |z| <= r, the four slabs
// |x +- z| <= r, |y +- z| <= r; empty (x > y) where it misses. Where
// s^(2/b) + |z|^(2/c) <= 1 with b, c >= 2, s + |z| <= s^(2/b) + |z|^(2/c)
// (each term in [0, 1]), and s, the (2/a)-norm of (x, y), is at least
// max(|x|, |y|): every shape with b, c >= 2 lies in the pyramid for r = 1.
vec2 bipyramidSpan(vec3 o, vec3 dir, float r) {
  vec4 po = vec4(o.x + o.z, o.x - o.z, o.y + o.z, o.y - o.z);
  vec4 pd = vec4(dir.x + dir.z, dir.x - dir.z, dir.y + dir.z, dir.y - dir.z);
  // Parallel to a slab: the whole line is inside it or none of it is.
  bvec4 edgeOn = equal(pd, vec4(0.0f));
  if (any(bvec4(vec4(edgeOn) * vec4(greaterThan(abs(po), vec4(r)))))) return vec2(1e38f, -1e38f);
  vec4 inv = 1.0f / mix(pd, vec4(1.0f), edgeOn);
  vec4 ta = (-r - po) * inv, tb = (r - po) * inv;
  vec4 lo = mix(min(ta, tb), vec4(-1e38f), edgeOn), hi = mix(max(ta, tb), vec4(1e38f), edgeOn);
  return vec2(max(max(lo.x, lo.y), max(lo.z, lo.w)), min(min(hi.x, hi.y), min(hi.z, hi.w)));
}

// Where along o + s dir (|dir| = 1, GC) the march can find a root: empty
// (x > y) where the ray cannot hit `shape`; in the mixed-sign variant the
// span in the double pyramid, with room for shape exponents a few ulps below
// 2, for the tolerance eps of a hit, and for float rounding; else all of it.
// Rounding scales with n = max|o_i|: the march takes the gauge at o + s dir
// rounded, |s| <= |o| + sqrt(3) inside the cube, up to 2^-22 (n + 2) off
// the line in the pyramid's measure, and the slab ends round by up to three
// times that; 2^-19 (n + 2) is twice the sum. n is large where a glyph is
// far thinner than wide (a zero eigenvalue) and seen at a slant: o, the
// ray's closest approach to the centre in VC, lies up to 1e7 out along GC z,
// and the march's points are that coarse (a pyramid 0.06 wide there was
// missed by rounding). The pyramid grows to match, and such rays march as
// before; so does a non-finite o.
vec2 marchSearchSpan(vec3 shape, vec3 o, vec3 dir, float eps, float n) {
#ifdef TG_MARCH_MIXED
  float r = 1.0f + 1e-3f + 4.0f * eps + exp2(-19.0f) * (n + 2.0f);
  if (min(shape.y, shape.z) >= 1.9999f && r < 1e30f) return bipyramidSpan(o, dir, r);
#endif
  return vec2(-1e38f, 1e38f);
}

const int kGridSamples = 24;

// Sample k of the grid search on [s0, s1]; the march takes its samples here.
float gridSample(float s0, float s1, int k) { return s0 + (s1 - s0) * float(k) / float(kGridSamples); }

// The grid samples whose intervals can bracket a root within `search`: from
// the last sample before its entry to the first after its exit. Outside it
// every gauge exceeds 1, so the samples left out bracket nothing, and the
// search from the first sample kept leaves the march as it was there.
void gridRange(float s0, float s1, vec2 search, TG_OUT(int) kFirst, TG_OUT(int) kLast) {
  float step = (s1 - s0) / float(kGridSamples);
  kFirst = search.x > s0 ? clamp(int(floor((search.x - s0) / step)), 0, kGridSamples) : 0;
  if (kFirst > 0 && !(gridSample(s0, s1, kFirst) < search.x)) --kFirst;
  if (kFirst > 0 && !(gridSample(s0, s1, kFirst) < search.x)) kFirst = 0;
  kLast = search.y < s1 ? clamp(int(ceil((search.y - s0) / step)), 0, kGridSamples) : kGridSamples;
  if (kLast < kGridSamples && !(gridSample(s0, s1, kLast) > search.y)) ++kLast;
  if (kLast < kGridSamples && !(gridSample(s0, s1, kLast) > search.y)) kLast = kGridSamples;
}

// The point whose gauge bounds the gauge on the segment from pa to pb
// from below: its |x|, |y|, |z| at their least over the segment, lowered by
// `rounding`, since every gauge grows with each of them. A margin proof
// that the segment holds no root, for any point the march rounds onto it.
vec3 segmentLowCorner(vec3 pa, vec3 pb, float rounding) {
  vec3 least = mix(min(abs(pa), abs(pb)), vec3(0.0f), lessThanEqual(pa * pb, vec3(0.0f)));
  return max(least - rounding, vec3(0.0f));
}

// How far above 1 a lower bound on the gauge must lie to rule out a root:
// far more than the float gauge's relative error.
const float kRootFreeMargin = 1e-2f;
// Bisection steps between proofs: on the point load, loop passes per 8-lane
// group were 1.181 M with a proof after every step, 1.161 M every second,
// 1.160 M every third and 1.182 M with one at the start only.
const int kBisectionsPerProof = 3;

const int kPhaseEntry = 0, kPhaseGrid = 1, kPhaseBisect = 2, kPhaseNewton = 3, kPhaseGradient = 4;

// The first surface crossing of the unit glyph along o + s dir (|dir| = 1,
// GC) with s >= sNear, to tolerance eps in GC units, in at most maxIter
// Newton steps. Seeded at the cube entry; the bracket [lo, hi] with
// h(lo) > 0 >= h(hi) is kept, and a step that leaves it falls back to
// regula falsi or bisection. The grid search of non-convex shapes covers
// only `search` (marchSearchSpan), which holds every root.
MarchResult superquadricMarch(vec3 shape, vec3 o, vec3 dir, float sNear, vec2 search, int maxIter, float eps) {
  MarchResult res = MarchResult(false, 0.0f, vec3(0.0f), 0, 0);
  vec2 span = unitCubeSpan(o, dir);
  float s0 = span.x, s1 = span.y;
  bool fromNear = sNear > s0;
  s0 = max(s0, sNear);
  if (!(s0 <= s1)) return res;

  int kFirst = 0, kLast = kGridSamples;
#ifndef TG_MARCH_CONVEX
  if (!superquadricConvex(shape)) gridRange(s0, s1, search, kFirst, kLast);
#endif
  int phase = kPhaseEntry;
  // Where this iteration takes the gauge: the cube entry, or for the grid
  // search the last sample before `search`, with no root before it.
  float s = kFirst > 0 ? gridSample(s0, s1, kFirst) : s0;
  bool exiting = false, bracketed = false, knownHi = false, lastFalsi = false, done = false;
  float lo = s0, hi = s1;
  // h at the bracket's ends, where known, for regula falsi.
  float hLo = 0.0f, hHi = 0.0f;
  // The grid: sample k at gridS, the sample before it at prev; a, b: the
  // derivative bisection's interval between them.
  int k = 0, j = 0, i = 0, finalIterations = 0;
  float prev = s, prevH = 0.0f, prevSlope = 0.0f, gridS = 0.0f, gridH = 0.0f, gridSlope = 0.0f, a = 0.0f, b = 0.0f;
  // The derivative bisection first tries to prove its interval root-free:
  // the gauge at `corner` (segmentLowCorner), taken instead of the next
  // sample, ends a search that could only fail; 2^-20 (max|o_i| + 2) bounds
  // where the march rounds the segment's points to (marchSearchSpan).
  bool proving = false;
  vec3 corner = vec3(0.0f);
  float rounding = exp2(-20.0f) * (max(max(abs(o.x), abs(o.y)), abs(o.z)) + 2.0f);
  int calls = 0;
  while (!done) {
    ++calls;
    vec3 grad;
    float h = superquadricGauge(shape, proving ? corner : o + s * dir, grad) - 1.0f;
    float slope = dot(grad, dir);
    bool nextSample = false;  // leave this grid sample for the next
    if (phase == kPhaseEntry) {
      hLo = h;
      if (isnan(h) || isinf(h)) {
        done = true;
      } else if (h <= 0.0f) {
        if (!fromNear) {
          res = MarchResult(true, s0, grad, 0, 0);  // the glyph touches the cube face
          done = true;
        } else {
          exiting = true;  // the near point is inside: find the exit
          bracketed = true;
          phase = kPhaseNewton;
          s = hi;
        }
#ifndef TG_MARCH_CONVEX
      } else if (!superquadricConvex(shape)) {
        // Non-convex: the first sign change on a coarse grid brackets the
        // root. A thin spike can pass between samples; where h' turns from
        // - to + the interval holds a local minimum, found by bisecting on
        // the sign of h' (Teem's echo searches the derivative the same way),
        // and a minimum with h <= 0 closes the bracket.
        prevH = h;
        prevSlope = slope;
        k = kFirst + 1;
        phase = kPhaseGrid;
        s = gridSample(s0, s1, k);
        done = k > kLast;
#endif
      } else {
        float q0, q1;
        // a, b <= 1: the glyph holds the unit sphere, so its entry bounds the root.
        if (shape.x <= 1.0f && shape.y <= 1.0f && unitSphereRoots(o, dir, q0, q1) && q0 >= s0) {
          hi = q0;
          bracketed = true;
        }
        phase = kPhaseNewton;
        s = lo;
      }
    } else if (phase == kPhaseGrid) {
      gridS = s;
      gridH = h;
      gridSlope = slope;
      if (h <= 0.0f) {
        bracketed = true;
      } else if (prevSlope < 0.0f && slope > 0.0f && s - prev > eps) {
        a = prev;
        b = s;
        j = 0;
        phase = kPhaseBisect;
        s = 0.5f * (a + b);
        proving = true;
        corner = segmentLowCorner(o + a * dir, o + b * dir, rounding);
      } else {
        nextSample = true;
      }
    } else if (phase == kPhaseBisect) {
      if (proving) {
        // No root in [a, b]: the bisection would end without one.
        proving = false;
        nextSample = h > kRootFreeMargin;
      } else if (h <= 0.0f) {
        gridS = s;
        gridH = h;
        bracketed = true;
      } else {
        if (slope < 0.0f) a = s;
        else b = s;
        ++j;
        if (j < kGridSamples && b - a > eps) s = 0.5f * (a + b);
        else nextSample = true;
        if (!nextSample && j % kBisectionsPerProof == 0) {
          proving = true;
          corner = segmentLowCorner(o + a * dir, o + b * dir, rounding);
        }
      }
    } else if (phase == kPhaseNewton) {
      res.iterations = i + 1;
      if (isnan(h) || isnan(slope)) {
        done = true;  // never report a hit from a NaN
      } else if (abs(h) < eps) {
        res = MarchResult(true, s, grad, i + 1, 0);
        done = true;
      } else {
        // Keep the bracket: the side with h > 0 is lo when entering, hi when exiting.
        if ((h > 0.0f) != exiting) {
          lo = s;
          hLo = h;
        } else {
          hi = s;
          hHi = h;
          knownHi = true;
        }
        if (h <= 0.0f) bracketed = true;
        float next = s - h / slope;
        // Miss: outside a convex glyph and moving away from it (Hlawitschka's
        // test). Unbracketed means convex and outside, where Newton never
        // overshoots (the tangent of a convex function lies below it): a step
        // past the cube exit proves there is no root. Bisecting there would
        // instead shrink an interval holding no root until the step
        // criterion took it for a hit.
        if (!bracketed && ((h > 0.0f && slope >= 0.0f) || !(next < hi))) {
          done = true;
        } else {
          // Newton left the bracket: Blinn's fallback, regula falsi on the
          // bracket's ends, alternating with bisection so that a one-sided
          // run of false positions still halves the bracket every second step.
          bool falsi = false;
          if (!(next > lo && next < hi)) {
            falsi = bracketed && knownHi && !lastFalsi && hLo != hHi;
            next = falsi ? lo - hLo * (hi - lo) / (hHi - hLo) : 0.5f * (lo + hi);
            if (!(next > lo && next < hi)) {
              next = 0.5f * (lo + hi);
              falsi = false;
            }
          }
          lastFalsi = falsi;
          // Step criterion (Hlawitschka et al.); a collapsed bracket only
          // counts when it is known to hold a root.
          if (abs(next - s) < eps || (bracketed && hi - lo < eps)) {
            finalIterations = i + 1;
            phase = kPhaseGradient;
          }
          s = next;
          ++i;
        }
      }
    } else {
      res = MarchResult(true, s, grad, finalIterations, 0);
      done = true;
    }
    if (phase == kPhaseGrid || phase == kPhaseBisect) {
      if (bracketed) {
        lo = prev;
        hLo = prevH;
        hi = gridS;
        hHi = gridH;
        knownHi = true;
        phase = kPhaseNewton;
        s = lo;
      } else if (nextSample) {
        prev = gridS;
        prevH = gridH;
        prevSlope = gridSlope;
        ++k;
        phase = kPhaseGrid;
        s = gridSample(s0, s1, k);
        done = k > kLast;  // no sign change: no root
      }
    }
    // Out of iterations: a bracketed root exists, so the pixel is covered at
    // the current estimate; an unbracketed one is not known to be hit.
    if (!done && phase == kPhaseNewton && i >= maxIter) {
      finalIterations = maxIter;
      phase = kPhaseGradient;
      done = !bracketed;
    }
  }
  res.gaugeCalls = calls;
  return res;
}
