// Glyph base colour. Modes match tg::render::ColorMode, colormaps
// tg::render::Colormap; src/render/color_scalar.cpp is the CPU twin of the
// scalars, which tests and the automatic windows read.
const int kColorDEC = 0, kColorFA = 1, kColorMD = 2, kColorCL = 3, kColorCP = 4, kColorSign = 5;
const int kColorVonMises = 6, kColorTresca = 7, kColorPressure = 8, kColorS1 = 9, kColorS2 = 10, kColorS3 = 11;
const int kColorTrace = 12, kColorDecFA = 13, kColorArray = 14;
const int kMapGray = 0, kMapViridis = 1, kMapDiverging = 2;

// Viridis (van der Walt & Smith, matplotlib), 9 samples; linear in between.
vec3 viridis(float t) {
  const vec3 c[9] = vec3[9](vec3(0.267, 0.005, 0.329), vec3(0.278, 0.175, 0.483), vec3(0.230, 0.322, 0.546),
                            vec3(0.173, 0.449, 0.558), vec3(0.128, 0.567, 0.551), vec3(0.153, 0.680, 0.504),
                            vec3(0.362, 0.786, 0.388), vec3(0.678, 0.864, 0.190), vec3(0.993, 0.906, 0.144));
  float x = clamp(t, 0.0, 1.0) * 8.0;
  int i = min(int(x), 7);
  return mix(c[i], c[i + 1], x - float(i));
}

// The diverging map over t in -1..1: blue (compression, negative) through
// white at 0 to orange (tension, positive); the sign colour and the legend's
// diverging bars draw it too.
vec3 signRamp(float t) {
  t = clamp(t, -1.0, 1.0);
  return t >= 0.0 ? mix(vec3(1.0), vec3(0.90, 0.42, 0.10), t) : mix(vec3(1.0), vec3(0.15, 0.40, 0.90), -t);
}

// Colormap `map` over t in 0..1 (diverging: its white at 0.5).
vec3 colormap(int map, float t) {
  t = clamp(t, 0.0, 1.0);
  return map == kMapViridis ? viridis(t) : map == kMapDiverging ? signRamp(2.0 * t - 1.0) : vec3(t);
}

// Directionally encoded colour as Teem's tenGlyphGen: |e1| as RGB, saturation
// scaled by FA towards the isotropic grey (Teem's defaults: grey 1, max sat 1).
vec3 decColor(vec3 e1WC, float fa) {
  return mix(vec3(1.0), abs(e1WC), clamp(fa, 0.0, 1.0));
}

// Westin's cl, cp from descending eigenvalues; 0 for non-positive trace.
vec2 westinLinearPlanar(vec3 l) {
  float tr = l.x + l.y + l.z;
  if (!(tr > 1e-12 * length(l))) return vec2(0.0);
  return vec2((l.x - l.y) / tr, 2.0 * (l.y - l.z) / tr);
}

// The scalar of a scalar mode from the descending eigenvalues l and FA
// (kColorArray's value is the caller's). Differences of the eigenvalues
// over their largest magnitude, so that squares neither overflow nor underflow.
float colorScalar(int mode, float fa, vec3 l) {
  float m = max(abs(l.x), max(abs(l.y), abs(l.z)));
  vec3 u = m > 0.0 ? l / m : vec3(0.0);
  if (mode == kColorFA) return fa;
  if (mode == kColorCL) return westinLinearPlanar(l).x;
  if (mode == kColorCP) return westinLinearPlanar(l).y;
  if (mode == kColorMD) return (u.x + u.y + u.z) / 3.0 * m;
  if (mode == kColorVonMises) {
    vec3 d = vec3(u.x - u.y, u.y - u.z, u.z - u.x);
    return sqrt(0.5 * dot(d, d)) * m;
  }
  if (mode == kColorTresca) return (u.x - u.z) * m;
  if (mode == kColorPressure) return -(u.x + u.y + u.z) / 3.0 * m;
  if (mode == kColorS1) return l.x;
  if (mode == kColorS2) return l.y;
  if (mode == kColorS3) return l.z;
  return (u.x + u.y + u.z) * m;  // kColorTrace
}

// A value on `map` over window (lo, hi): halved first, as a window from
// -3e38 to 3e38 is wider than a float holds; a flat window gives the
// map's middle, a NaN (an array's missing value) mid grey.
vec3 windowColor(int map, vec2 window, float v) {
  if (isnan(v)) return vec3(0.5);
  float span = 0.5 * window.y - 0.5 * window.x;
  return colormap(map, span > 0.0 ? (0.5 * v - 0.5 * window.x) / span : 0.5);
}

// Every mode but kColorSign, whose colour is per surface point (signColor).
vec3 glyphColor(int mode, int map, vec2 window, vec3 e1WC, float fa, vec3 eigenvalues, float arrayValue) {
  if (mode == kColorDEC) return decColor(e1WC, fa);
  if (mode == kColorDecFA) return abs(e1WC) * clamp(fa, 0.0, 1.0);
  return windowColor(map, window, mode == kColorArray ? arrayValue : colorScalar(mode, fa, eigenvalues));
}

// Sign colouring for stress (kColorSign), per surface point: the normal
// stress r.D.r along the unit direction r from the glyph's centre to the
// point, over M, the window's largest |value| (by default the field's
// largest |eigenvalue|), on the diverging map: orange where positive
// (tension), blue where negative (compression), white where it vanishes,
// saturated only at |r.D.r| = M. The vertex stage passes the eigenvalues
// over M in GC order (signWeights); with a the semi-axes and p the
// unit-glyph point, r.D.r = sum lambda_k a_k^2 p_k^2 / sum a_k^2 p_k^2.
vec3 signWeights(vec3 eigenvaluesGC, vec2 window) {
  float m = max(abs(window.x), abs(window.y));
  return m > 0.0 ? eigenvaluesGC / m : vec3(0.0);
}

// gcFromVC's rows are the GC axes in VC over their semi-axes a_k: a_k^2
// relative to the largest, scaled first so that no square overflows.
vec3 relativeAxesSquared(mat3 gcFromVC) {
  mat3 rows = transpose(gcFromVC);
  float s = 0.0;
  for (int k = 0; k < 3; ++k) s = max(s, max(abs(rows[k].x), max(abs(rows[k].y), abs(rows[k].z))));
  if (!(s > 0.0)) return vec3(1.0);
  vec3 len = vec3(length(rows[0] / s), length(rows[1] / s), length(rows[2] / s));
  vec3 rel = min(len.x, min(len.y, len.z)) / len;  // a_k / max a
  return rel * rel;
}

vec3 signColor(vec3 weightsGC, vec3 pGC, mat3 gcFromVC) {
  vec3 a2p2 = relativeAxesSquared(gcFromVC) * pGC * pGC;
  float r2 = a2p2.x + a2p2.y + a2p2.z;
  return signRamp(r2 > 0.0 ? dot(weightsGC, a2p2) / r2 : 0.0);
}
