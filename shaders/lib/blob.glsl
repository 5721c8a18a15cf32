// Blinn's blobby surfaces (Blinn 1982) over tensor glyphs. Each glyph is a
// bump D_i = exp(B (g_i^2 - 1)) whose exponent is its glyph's quadric
// (Blinn §6.1, general quadric seeds: g_i = |p_GC|) or, at gamma > 0, its
// superquadric gauge (§6.3, hyperellipsoids: lib/superquadric.glsl's
// superquadricGauge), so that D_i = 1 on the glyph's own surface and an
// isolated glyph's blob at threshold T = 1 is the glyph itself. The surface
// is sum_i D'_i = T. Each bump is truncated where it falls to the cutoff
// t T (§3.6's enclosing region, there a sphere, here the glyph's ellipsoid
// grown to that gauge) and shifted so that it stays continuous and the
// isolated surface stays where it was:
//   D'_i = max(D_i - t T, 0) / (1 - t),
// within t T / (1 - t) of D_i everywhere; so the sum is within K t T / (1 - t)
// of the untruncated one where K bumps' regions overlap (docs/design.md,
// "Blobs"). In the GLSL/C++ subset (lib/glsl_cpp.h). Requires lib/camera.glsl,
// lib/glyph_record_type.glsl, lib/ellipsoid.glsl, lib/glyph_size.glsl,
// lib/superquadric.glsl, lib/selection.glsl and lib/pixel_centres.glsl.
uniform float uBlobBlobbiness;  // Blinn's B, < 0: the larger |B|, the less neighbours blend
uniform float uBlobThreshold;   // T > 0
uniform float uBlobCutoff;      // t in (0, 1)

// Mirrors tg::tensor::kBlobMinAxisRatio: a bump's thinnest semi-axis relative to its longest.
const float kBlobMinAxisRatio = 1e-3f;

// The gauge at which a bump falls to the cutoff: D_i = t T at
// g^2 = 1 + ln(t T) / B; 0 where even its peak exp(-B) stays below t T.
float blobBoundGauge() {
  float s = 1.0f + log(uBlobCutoff * uBlobThreshold) / uBlobBlobbiness;
  return s > 0.0f ? sqrt(s) : 0.0f;
}

struct BlobBump {
  vec3 centreVC;
  mat3 gcFromVC;  // rows: the GC axes in VC over their semi-axes (g = 1 on the glyph)
  vec4 shape;     // superquadricShape at gamma; (1, 1, 1, 2), the quadric, at gamma 0
  float reachGC;  // no point of the truncated bump lies farther from the GC origin
  float nearVC;   // nor nearer the eye than this view depth
  vec4 rectNDC;   // (xmin, ymin, xmax, ymax) of its region, grown by a quarter pixel
};

bool blobIsQuadric(vec4 shape) { return shape.x == 1.0f && shape.y == 1.0f && shape.z == 1.0f; }

// False where no pixel centre's ray meets glyph g's truncated bump:
// unselected, of no size, beyond the depth range or off screen.
bool blobBump(GlyphRecord g, float gamma, float boundGauge, TG_OUT(BlobBump) b) {
  if (!glyphSelected(g.posWC_fa) || !(boundGauge > 0.0f)) return false;
  vec3 axes = glyphAxes(vec3(g.eigenvalues_id));
  float radius = max(axes.x, max(axes.y, axes.z));
  if (!(radius > 0.0f)) return false;
  axes = max(axes, vec3(kBlobMinAxisRatio * radius));
  b.shape = gamma > 0.0f ? superquadricShape(vec3(g.eigenvalues_id), gamma) : vec4(1.0f, 1.0f, 1.0f, 2.0f);
  // The unit shape lies within its reach of the GC origin, and g is
  // homogeneous of degree 1: the region g <= boundGauge within their product.
  b.reachGC = boundGauge * superquadricReach(vec3(b.shape));
  b.centreVC = vec3(uViewWCVC * vec4(vec3(g.posWC_fa), 1.0f));
  float reachVC = b.reachGC * radius;
  if (-b.centreVC.z + reachVC < uNearVC || (uOrtho == 1 && -b.centreVC.z - reachVC > uFarVC)) return false;
  if (spriteMissesEveryPixelCentre(b.centreVC, reachVC)) return false;
  mat3 rotVC = mat3(uViewWCVC) * quatToMat3(g.frameWC);
  // GC axes as the superquadric's: the cyclic permutation that puts its symmetry axis on z.
  int ax = int(b.shape.w);
  ivec3 src = ivec3((ax + 1) % 3, (ax + 2) % 3, ax);
  vec3 e0 = rotVC[src.x] * axes[src.x], e1 = rotVC[src.y] * axes[src.y], e2 = rotVC[src.z] * axes[src.z];
  b.gcFromVC = transpose(mat3(e0 / dot(e0, e0), e1 / dot(e1, e1), e2 / dot(e2, e2)));
  b.nearVC = max(-b.centreVC.z - reachVC, uNearVC);
  float k = b.reachGC;
  mat4 boundCC = uProjVCCC * mat4(vec4(k * e0, 0.0f), vec4(k * e1, 0.0f), vec4(k * e2, 0.0f), vec4(b.centreVC, 1.0f));
  vec4 rect;
  if (!ellipsoidRectNDC(boundCC, rect)) rect = vec4(-1.0f, -1.0f, 1.0f, 1.0f);
  else if (!blobIsQuadric(b.shape)) {
    // A superquadric's region also lies in its cube |q_k| <= boundGauge, whose
    // corners bound a boxy shape tighter than the grown ellipsoid does.
    float m = boundGauge;
    vec4 box = vec4(1e38f, 1e38f, -1e38f, -1e38f);
    bool behind = false;
    for (int c = 0; c < 8; ++c) {
      vec3 p = b.centreVC + m * (((c & 1) == 0 ? -e0 : e0) + ((c & 2) == 0 ? -e1 : e1) + ((c & 4) == 0 ? -e2 : e2));
      vec4 cc = uProjVCCC * vec4(p, 1.0f);
      if (cc.w <= 0.0f) behind = true;
      vec2 ndc = vec2(cc) / cc.w;
      box = vec4(min(vec2(box), ndc), max(vec2(box.z, box.w), ndc));
    }
    if (!behind) rect = vec4(max(vec2(rect), vec2(box)), min(vec2(rect.z, rect.w), vec2(box.z, box.w)));
  }
  if (rectMissesEveryPixelCentre(rect, kPixelCentreMarginDC)) return false;
  vec2 px = 0.5f / uViewportDC;
  b.rectNDC = clamp(rect + vec4(-px, px), -1.0f, 1.0f);
  return !(b.rectNDC.x >= b.rectNDC.z || b.rectNDC.y >= b.rectNDC.w);
}

// D'_i at GC point q (the truncated, shifted bump), with its GC gradient
// when `withGrad`.
float blobField(vec4 shape, vec3 q, float boundGauge, bool withGrad, TG_OUT(vec3) gradGC) {
  float g2;
  vec3 dg2 = vec3(0.0f);  // d(g^2)/dq
  if (blobIsQuadric(shape)) {
    g2 = dot(q, q);
    dg2 = 2.0f * q;
  } else {
    // Every shape lies within its cube, so g >= max |q_k|: beyond the
    // bound's cube the bump adds nothing, and needs no gauge.
    vec3 aq = abs(q);
    if (!(max(aq.x, max(aq.y, aq.z)) < boundGauge)) {
      gradGC = vec3(0.0f);
      return 0.0f;
    }
    vec3 grad = vec3(0.0f);
    float gauge = withGrad ? superquadricGauge(vec3(shape), q, grad) : superquadricGaugeValue(vec3(shape), q);
    g2 = gauge * gauge;
    dg2 = 2.0f * gauge * grad;
  }
  gradGC = vec3(0.0f);
  if (!(g2 < boundGauge * boundGauge)) return 0.0f;
  float d = exp(uBlobBlobbiness * (g2 - 1.0f));
  float cut = uBlobCutoff * uBlobThreshold, norm = 1.0f / (1.0f - uBlobCutoff);
  if (withGrad) gradGC = (d * uBlobBlobbiness * norm) * dg2;
  return max(d - cut, 0.0f) * norm;
}
