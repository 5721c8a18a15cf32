// A glyph's ellipsoid as the sprite stages and the CPU glyph path set it up:
// the selection and the culls that need no neighbour, then its exact screen
// rectangle (Sigg et al. 2006, eq. 5). In the GLSL/C++ subset
// (lib/glsl_cpp.h). Requires lib/camera.glsl, lib/glyph_record_type.glsl,
// lib/ellipsoid.glsl, lib/glyph_size.glsl, lib/selection.glsl and
// lib/pixel_centres.glsl.
struct EllipsoidSprite {
  vec3 axes;       // semi-axes in WC
  float radius;    // the longest
  vec3 centreVC;
  float dist;      // the centre's view depth
  mat3 rotWC;      // GC axes in WC
  mat3 rotVC;      // and in VC
  mat4 tVC;        // parameter -> view (ellipsoidTVC)
  vec4 rectNDC;    // (xmin, ymin, xmax, ymax), grown by a quarter pixel, within the viewport
};

// False where no pixel centre can see glyph g: unselected, of no size,
// beyond the depth range, or its rectangle holding no pixel centre.
bool ellipsoidSprite(GlyphRecord g, TG_OUT(EllipsoidSprite) s) {
  if (!glyphSelected(g.posWC_fa)) return false;
  s.axes = glyphAxes(vec3(g.eigenvalues_id));
  s.radius = max(s.axes.x, max(s.axes.y, s.axes.z));
  if (!(s.radius > 0.0f)) return false;
  s.centreVC = vec3(uViewWCVC * vec4(vec3(g.posWC_fa), 1.0f));
  s.dist = -s.centreVC.z;
  if (s.dist + s.radius < uNearVC || (uOrtho == 1 && s.dist - s.radius > uFarVC)) return false;
  // The sphere of the longest axis holds the ellipsoid.
  if (spriteMissesEveryPixelCentre(s.centreVC, s.radius)) return false;
  s.rotWC = quatToMat3(g.frameWC);
  s.rotVC = mat3(uViewWCVC) * s.rotWC;
  s.tVC = ellipsoidTVC(s.rotVC, s.axes, s.centreVC);
  if (!ellipsoidFrameRectNDC(mat3(s.tVC), s.centreVC, s.rectNDC)) s.rectNDC = vec4(-1.0f, -1.0f, 1.0f, 1.0f);
  else if (rectMissesEveryPixelCentre(s.rectNDC, kPixelCentreMarginDC)) return false;
  // A quarter pixel of margin so that pixel centres on the exact edge are kept.
  vec2 px = 0.5f / uViewportDC;
  s.rectNDC = clamp(s.rectNDC + vec4(-px, px), -1.0f, 1.0f);
  return !(s.rectNDC.x >= s.rectNDC.z || s.rectNDC.y >= s.rectNDC.w);
}
