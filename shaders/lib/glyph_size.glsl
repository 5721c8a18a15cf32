// A glyph's size: its eigenvalues times one factor of its own, so that the
// magnitude mapping and the clamp keep its shape ratios. Mirrors
// tg::tensor::glyphFactor (src/tensor/glyph_scale.h). Requires lib/ellipsoid.glsl.
uniform float uScale;         // world units per (mapped) eigenvalue unit
uniform int uMagnitude;       // 0 linear, 1 log, 2 shape (tg::tensor::Magnitude)
uniform float uLambda0;       // log knee; shape's fixed size
uniform float uMaxRadiusWC;   // clamp on the largest semi-axis; 0: none

// World units per eigenvalue unit for a glyph whose largest |eigenvalue| is m:
// exactly uScale when linear and unclamped.
float glyphFactor(float m) {
  float k = uScale;
  if (!(m > 0.0f)) return k;
  if (uMagnitude == 1) {
    // ln(1 + x) / x, with its series below 1e-3 where 1 + x rounds away x.
    float x = m / uLambda0;
    k *= x < 1e-3f ? 1.0f - x * (0.5f - x / 3.0f) : log(1.0f + x) / x;
  } else if (uMagnitude == 2) {
    k *= uLambda0 / m;
  }
  if (uMaxRadiusWC > 0.0f && k * m > uMaxRadiusWC) k = uMaxRadiusWC / m;
  return k;
}

// The largest semi-axis of a glyph of magnitude m (non-decreasing in m).
float glyphRadiusWC(float m) { return glyphFactor(m) * m; }

vec3 glyphAxes(vec3 eigenvalues) {
  vec3 a = abs(eigenvalues);
  return ellipsoidAxes(eigenvalues, glyphFactor(max(a.x, a.z)));
}
