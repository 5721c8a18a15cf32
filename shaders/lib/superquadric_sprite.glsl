// A superquadric glyph as the sprite stage (superquadric.vert) and the CPU
// glyph path set it up: the selection and the culls that need no
// neighbour, the shape from the record and gamma, and the exact screen
// rectangle of the glyph's box (the gamma -> infinity limit that holds every
// shape; Hlawitschka et al. §3.2), tightened by the ellipsoid grown by the
// shape's reach and, in the mixed-sign variant, by the double pyramid. In
// the GLSL/C++ subset (lib/glsl_cpp.h). Requires lib/camera.glsl,
// lib/glyph_record_type.glsl, lib/ellipsoid.glsl, lib/glyph_size.glsl,
// lib/superquadric.glsl, lib/selection.glsl and lib/pixel_centres.glsl.
// TG_MARCH_MIXED: the mixed-sign group's variant (superquadric.vert's option).
struct SuperquadricSprite {
  vec3 axes;       // semi-axes in WC
  vec3 centreVC;
  vec4 shape;      // (a, b, c) and the eigenvector GC z follows (superquadricShape)
  ivec3 src;       // GC axis k is eigenvector src[k]: a cyclic permutation
  mat3 rotWC;      // eigenvectors in WC
  vec3 e0, e1, e2;  // GC axes in VC times their semi-axes
  mat3 gcFromVC;   // rows: GC axes in VC over their lengths
  float nearest;   // no point of the box is nearer (view depth)
  float nearVC;    // no hit of the march is nearer: the sprite's depth
  bool crossesEyePlane;
  bool pyramid;    // the mixed-sign outline holds the glyph
  vec2 boxNDC[8];  // the box's corners
  vec2 pyramidNDC[6];  // the double pyramid's, grown as the march grows it
  mat4 reachCC;    // parameter -> clip of the ellipsoid grown by the reach
  vec2 sizeDC;     // the rectangle's size in pixels, before its margin
  vec4 rectNDC;    // (xmin, ymin, xmax, ymax), grown by a quarter pixel, within the viewport
};

// The glyph's frame, what a cast needs (axes, centreVC, shape, rotWC, src,
// e0..e2, gcFromVC), for semi-axes `axes` and view centre `centreVC`.
void superquadricFrame(GlyphRecord g, vec3 axes, vec3 centreVC, float gamma, TG_OUT(SuperquadricSprite) s) {
  s.axes = axes;
  s.centreVC = centreVC;
  s.shape = superquadricShape(vec3(g.eigenvalues_id), gamma);
  s.rotWC = quatToMat3(g.frameWC);
  mat3 rotVC = mat3(uViewWCVC) * s.rotWC;
  // GC axes: a cyclic permutation of the eigenvectors that puts the symmetry axis on z.
  int ax = int(s.shape.w);
  s.src = ivec3((ax + 1) % 3, (ax + 2) % 3, ax);
  s.e0 = rotVC[s.src.x] * s.axes[s.src.x];
  s.e1 = rotVC[s.src.y] * s.axes[s.src.y];
  s.e2 = rotVC[s.src.z] * s.axes[s.src.z];
  s.gcFromVC = transpose(mat3(s.e0 / dot(s.e0, s.e0), s.e1 / dot(s.e1, s.e1), s.e2 / dot(s.e2, s.e2)));
}

// False where no pixel centre can see glyph g at sharpness gamma and march
// tolerance eps: unselected, of no size, beyond the depth range, or its
// rectangle holding no pixel centre.
bool superquadricSprite(GlyphRecord g, float gamma, float eps, TG_OUT(SuperquadricSprite) s) {
  if (!glyphSelected(g.posWC_fa)) return false;
  vec3 axes = glyphAxes(vec3(g.eigenvalues_id));
  if (!(max(axes.x, max(axes.y, axes.z)) > 0.0f)) return false;
  vec3 centreVC = vec3(uViewWCVC * vec4(vec3(g.posWC_fa), 1.0f));
  // The box's half-diagonal bounds every shape.
  if (spriteMissesEveryPixelCentre(centreVC, length(axes))) return false;
  superquadricFrame(g, axes, centreVC, gamma, s);
  vec3 e0 = s.e0, e1 = s.e1, e2 = s.e2;

  // The box's corners: nearest depth, and their projected rectangle.
  float nearest = 1e38f;
  vec4 rect = vec4(1e38f, 1e38f, -1e38f, -1e38f);
  s.crossesEyePlane = false;
  for (int k = 0; k < 8; ++k) {
    vec3 c = s.centreVC + ((k & 1) == 0 ? -e0 : e0) + ((k & 2) == 0 ? -e1 : e1) + ((k & 4) == 0 ? -e2 : e2);
    nearest = min(nearest, -c.z);
    vec4 cc = uProjVCCC * vec4(c, 1.0f);
    if (cc.w <= 0.0f) s.crossesEyePlane = true;
    s.boxNDC[k] = vec2(cc) / cc.w;
    rect = vec4(min(vec2(rect), s.boxNDC[k]), max(vec2(rect.z, rect.w), s.boxNDC[k]));
  }
  // Mixed-sign shapes (b, c >= 2) also lie in the double pyramid
  // max(|x|, |y|) + |z| <= 1 in GC (lib/superquadric_march.glsl), grown as
  // the fragment stage grows it for shape exponents just below 2 and the
  // march's tolerance (float rounding in window pixels is left to the
  // sprites' margins): its six corners bound a thin glyph's outline tighter
  // than the box's eight.
#ifdef TG_MARCH_MIXED
  s.pyramid = min(s.shape.y, s.shape.z) >= 1.9999f;
#else
  s.pyramid = false;  // a constant: the compiler drops every use
#endif
  float rP = 1.0f + 1e-3f + 4.0f * eps;
  vec4 rectP = vec4(1e38f, 1e38f, -1e38f, -1e38f);
  for (int k = 0; k < 6; ++k) {
    vec3 c = s.centreVC + rP * (k < 4 ? ((k & 1) == 0 ? -e0 : e0) + ((k & 2) == 0 ? -e1 : e1) : (k == 4 ? -e2 : e2));
    vec4 cc = uProjVCCC * vec4(c, 1.0f);
    if (cc.w <= 0.0f) s.pyramid = false;
    s.pyramidNDC[k] = vec2(cc) / cc.w;
    rectP = vec4(min(vec2(rectP), s.pyramidNDC[k]), max(vec2(rectP.z, rectP.w), s.pyramidNDC[k]));
  }
  if (s.pyramid) rect = vec4(max(vec2(rect), vec2(rectP)), min(vec2(rect.z, rect.w), vec2(rectP.z, rectP.w)));
  float farthest = -s.centreVC.z + length(s.axes);
  if (farthest < uNearVC || (uOrtho == 1 && nearest > uFarVC)) return false;
  if (s.crossesEyePlane) rect = vec4(-1.0f, -1.0f, 1.0f, 1.0f);
  // The shape also lies within its ellipsoid grown by its reach: where that
  // ellipsoid's rectangle is tighter than the box's (a rotated box's corners
  // reach far out), only pixels that cannot hit are left out.
  float reach = superquadricReach(vec3(s.shape));
  float radius = max(s.axes.x, max(s.axes.y, s.axes.z));
  s.nearest = max(nearest, -s.centreVC.z - reach * radius);
  s.reachCC = uProjVCCC * mat4(vec4(reach * e0, 0.0f), vec4(reach * e1, 0.0f), vec4(reach * e2, 0.0f),
                               vec4(s.centreVC, 1.0f));
  vec4 rectR;
  if (!s.crossesEyePlane && ellipsoidRectNDC(s.reachCC, rectR))
    rect = vec4(max(vec2(rect), vec2(rectR)), min(vec2(rect.z, rect.w), vec2(rectR.z, rectR.w)));
  // No pixel centre in it (a glyph near a pixel's size, or thin): nothing to
  // set up. The march accepts hits within its tolerance, a glyph grown by at
  // most that fraction, so the margin grows with the rectangle.
  s.sizeDC = (vec2(rect.z, rect.w) - vec2(rect)) * 0.5f * uViewportDC;
  float marginDC = kPixelCentreMarginDC + (2e-3f + 4.0f * eps) * max(s.sizeDC.x, s.sizeDC.y);
  if (!s.crossesEyePlane && rectMissesEveryPixelCentre(rect, marginDC)) return false;
  // A quarter pixel of margin so that pixel centres on the exact edge are kept.
  vec2 px = 0.5f / uViewportDC;
  s.rectNDC = clamp(rect + vec4(-px, px), -1.0f, 1.0f);
  if (s.rectNDC.x >= s.rectNDC.z || s.rectNDC.y >= s.rectNDC.w) return false;
  // The march accepts hits up to its tolerance in front of the shape, so the
  // sprite lies that much nearer (superquadric.frag promises depth_less).
  s.nearVC = max(s.nearest - 4.0f * eps * radius, uNearVC);
  return true;
}
