// Whether any pixel centre can see a glyph, from bounds on its screen
// rectangle: a glyph that no ray through a pixel centre can hit draws
// nothing, so the vertex stage (lib/sprite.glsl) and llvmpipe's per-frame
// cull (cull_pixels.comp) drop it before its shape, primitive or fragments
// cost anything. Requires lib/camera.glsl and lib/ellipsoid.glsl.
// In the GLSL/C++ subset (lib/glsl_cpp.h).

// True where no pixel centre lies in rectNDC (xmin, ymin, xmax, ymax) grown
// by marginDC pixels on every side.
bool rectMissesEveryPixelCentre(vec4 rectNDC, float marginDC) {
  vec4 rectDC = (rectNDC + 1.0f) * 0.5f * vec4(uViewportDC, uViewportDC);
  // Pixel centres sit at k + 0.5: the first one at or past the low edge.
  vec2 firstCentre = ceil(vec2(rectDC) - marginDC - 0.5f) + 0.5f;
  return any(greaterThan(firstCentre, vec2(rectDC.z, rectDC.w) + marginDC));
}

// A 64th of a pixel of margin covers an exact rectangle's float rounding.
const float kPixelCentreMarginDC = 1.0f / 64.0f;

// True where no pixel centre lies in the screen rectangle of the sphere of
// radius rVC about centreVC, which holds the glyph: sub-pixel glyphs, most
// of a dense far field. No claim where the sphere meets the eye plane.
bool spriteMissesEveryPixelCentre(vec3 centreVC, float rVC) {
  vec4 rectNDC;
  if (!ellipsoidFrameRectNDC(mat3(rVC), centreVC, rectNDC)) return false;
  return rectMissesEveryPixelCentre(rectNDC, kPixelCentreMarginDC);
}
