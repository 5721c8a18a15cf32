// Glyph base colour. Modes match tg::render::ColorMode.
const int kColorDEC = 0, kColorFA = 1, kColorMD = 2, kColorCL = 3, kColorCP = 4, kColorSign = 5;

// Viridis (van der Walt & Smith, matplotlib), 9 samples; linear in between.
vec3 viridis(float t) {
  const vec3 c[9] = vec3[9](vec3(0.267, 0.005, 0.329), vec3(0.278, 0.175, 0.483), vec3(0.230, 0.322, 0.546),
                            vec3(0.173, 0.449, 0.558), vec3(0.128, 0.567, 0.551), vec3(0.153, 0.680, 0.504),
                            vec3(0.362, 0.786, 0.388), vec3(0.678, 0.864, 0.190), vec3(0.993, 0.906, 0.144));
  float x = clamp(t, 0.0, 1.0) * 8.0;
  int i = min(int(x), 7);
  return mix(c[i], c[i + 1], x - float(i));
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

vec3 glyphColor(int mode, vec3 e1WC, float fa, vec3 eigenvalues, vec2 mdRange) {
  if (mode == kColorDEC) return decColor(e1WC, fa);
  if (mode == kColorFA) return viridis(fa);
  if (mode == kColorMD) {
    float md = (eigenvalues.x + eigenvalues.y + eigenvalues.z) / 3.0;
    float span = mdRange.y - mdRange.x;
    return viridis(span > 0.0 ? (md - mdRange.x) / span : 0.5);
  }
  vec2 c = westinLinearPlanar(eigenvalues);
  return viridis(mode == kColorCL ? c.x : c.y);
}

// Sign colouring for stress (kColorSign), per surface point: the normal
// stress r.D.r along the direction r from the centre to the point, on a
// diverging map, orange where positive (tension), blue where negative
// (compression), white where it vanishes. Per GC axis k, weight_k =
// lambda_k * axis_k^2, both normalised so that tiny or huge fields neither
// underflow nor overflow; then r.D.r is proportional to sum weight_k p_k^2
// for the unit-glyph point p.
vec3 signWeights(vec3 eigenvalues, vec3 axes) {
  float l = max(abs(eigenvalues.x), max(abs(eigenvalues.y), abs(eigenvalues.z)));
  vec3 a = axes / max(axes.x, max(axes.y, axes.z));
  return l > 0.0 ? eigenvalues / l * a * a : vec3(0.0);
}

// The diverging map over t in -1..1; the legend's sign bar draws it too.
vec3 signRamp(float t) {
  return t >= 0.0 ? mix(vec3(1.0), vec3(0.90, 0.42, 0.10), t) : mix(vec3(1.0), vec3(0.15, 0.40, 0.90), -t);
}

vec3 signColor(vec3 weightsGC, vec3 pGC) {
  vec3 p2 = pGC * pGC;
  float m = dot(abs(weightsGC), p2);
  float t = m > 0.0 ? dot(weightsGC, p2) / m : 0.0;
  return signRamp(t);
}
