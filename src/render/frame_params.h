#pragma once
// What one frame is drawn with: every parameter the renderer, the CLI, the
// viewer, its scripts, Python and ParaView set. GL-free, so that option
// handling includes this rather than the renderer.
#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/glyph_kind.h"
#include "tensor/glyph.h"
#include "render/legend_params.h"
#include "tensor/glyph_scale.h"
#include "view/underlay.h"

namespace tg::render {

// The glyphs' colour (shaders/lib/color.glsl): directions (DEC, DecFA: |e1|
// times FA, dark where isotropic), the per-point sign of the normal stress,
// or a scalar on a colormap: derived from the eigenvalues (render/color_scalar.h)
// or, Array, one value per glyph given beside the records.
enum class ColorMode {
  DEC = 0, FA = 1, MD = 2, CL = 3, CP = 4, Sign = 5,
  VonMises = 6, Tresca = 7, Pressure = 8, S1 = 9, S2 = 10, S3 = 11, Trace = 12, DecFA = 13, Array = 14
};
inline constexpr int kColorModeCount = 15;

struct Lighting {
  glm::vec3 keyDirVC{-0.45f, 0.55f, 0.70f};  // upper left, in front
  float ambient = 0.22f, head = 0.55f, key = 0.40f, specular = 0.25f, shininess = 40.0f;
  bool operator==(const Lighting&) const = default;
};

// Blinn's blobs (GlyphKind::Blob; shaders/lib/blob.glsl): each glyph a bump
// exp(B (g^2 - 1)), 1 on its own surface; the surface where their sum is
// `threshold`. The defaults come from `tensorglyph bench accuracy --glyph
// blob` (docs/performance.md, "Blobs").
struct BlobParams {
  double threshold = 1.0;    // T > 0: at 1 an isolated glyph's blob is the glyph
  double blobbiness = -2.0;  // Blinn's B < 0: the larger |B|, the less neighbours blend
  double cutoff = 1e-3;      // t in (0, 1): a bump ends where it falls to t T
  int steps = 4;             // samples of the sum along a ray between a bump's entry, peak and exit
  bool operator==(const BlobParams&) const = default;
};

// Newton march settings; the defaults come from `tensorglyph bench accuracy`
// (docs/performance.md, "Speed against accuracy of the superquadric march").
struct MarchParams {
  int maxIterations = 10;
  double epsilon = 1e-4;  // in units of the glyph's size
  bool operator==(const MarchParams&) const = default;
};

// The march's programs (shaders/lib/superquadric_march.glsl): the general
// one, one for definite glyphs' convex shapes and one for mixed-sign
// glyphs' Schultz-Kindlmann shapes, each exact for its group.
enum class MarchVariant { General = 0, Convex = 1, Mixed = 2 };

struct AoParams {
  bool enabled = false;
  // Sample radius in world units; 0 picks kAutoRadius typical glyph
  // diameters (GlyphRenderer::aoRadiusWC), which follows the glyph scale.
  double radius = 0.0;
  // Occlusion weight: 0 leaves the light alone, 1 takes all ambient and
  // head light from a fully occluded point.
  double strength = 1.0;
  int samples = 16;  // hemisphere points per pixel
  static constexpr double kAutoRadius = 1.0;
  static constexpr int kMinSamples = 4, kMaxSamples = 64;
  static constexpr double kMaxStrength = 4.0;
  bool operator==(const AoParams&) const = default;
};

struct OutlineParams {
  bool enabled = false;
  double width = 1.5;                       // pixels
  glm::vec4 color{0.0f, 0.0f, 0.0f, 1.0f};  // RGBA, alpha blends the line over the glyph
  double creaseDeg = 45.0;                  // normals turning more than this make a crease
  static constexpr double kMaxWidth = 8.0;
  bool operator==(const OutlineParams&) const = default;
};

// One home for the shadow options: the CLI, the viewer and scripts read these
// defaults. Lengths in map texels are of the light-space map, so that they
// keep their meaning when the map is fitted to another region.
struct ShadowParams {
  bool enabled = false;
  int mapSize = 2048;  // texels per side of the square map, at most (see mapDensity)
  // Map texels per view pixel at the glyph box's centre: the map's side is
  // that, in multiples of 64, up to mapSize. A map finer than the view
  // resolves nothing more and costs as a second geometry pass at its size.
  // 0: always mapSize.
  float mapDensity = 1.0f;
  // Width of the soft edge (the PCF kernel) as a fraction of the map's side
  // in world units: independent of mapSize, which sets only its sharpness.
  float penumbra = 0.004f;
  float strength = 1.0f;  // share of the key light removed in full shadow
  // Depth of each PCF texel compared against the receiver's tangent plane
  // there (exact G-buffer normals): a plane has no acne at any slope, and a
  // convex glyph curves away from the light, never into its own shadow.
  bool receiverPlane = true;
  float bias = 0.5f;          // constant, along the light, in map texels
  float normalOffset = 0.0f;  // lookup moved along the normal, in map texels (the classic remedy)
  bool operator==(const ShadowParams&) const = default;
};

inline constexpr int kMinShadowMapSize = 64, kMaxShadowMapSize = 8192;
inline constexpr float kMaxShadowPenumbra = 0.1f, kMaxShadowBias = 64.0f;

// Glyphs whose centre lies in [lo, hi] along a WC axis (ParaView's and
// Slicer's slice of a glyph volume, as thick as asked), or along normalWC
// where it is given: a slice of an oblique grid (the viewer's `slab`).
struct Slab {
  int axis = -1;  // 0, 1, 2; -1: off
  double lo = 0, hi = 0;
  glm::dvec3 normalWC{0.0};  // unit; zero: along `axis`
  // The direction lo and hi are measured along.
  glm::dvec3 direction() const {
    if (normalWC != glm::dvec3(0.0) || axis < 0) return normalWC;
    glm::dvec3 e(0.0);
    e[axis] = 1.0;
    return e;
  }
  bool operator==(const Slab&) const = default;
};

struct FrameParams {
  double scale = 1.0;  // world units per eigenvalue unit
  tensor::SizeMapping sizing;  // magnitude mapping and clamp (tensor/glyph_scale.h); default: none
  double faMin = 0.0;
  Slab slab;
  GlyphKind glyph = GlyphKind::Ellipsoid;
  double gamma = 3.0;  // superquadric sharpness; 0 makes definite tensors ellipsoids
  MarchParams march;
  BlobParams blob;
  // Colour samples per pixel where the id changes within it (render/antialias_pass.h); 1: the pixel centre's alone.
  int samples = 1;
  bool iterationStats = false;  // count Newton iterations (a shader variant; off costs nothing)
  bool frustumCulling = true;  // off only to measure what it saves
  // Superquadrics: an exact ellipsoid depth pass first, so that fragments of
  // glyphs hidden behind it skip the march (off only to measure what it saves).
  bool occlusionPrepass = true;
  // Superquadrics: definite and mixed-sign glyphs by their march variants,
  // else by the general march (off only to compare).
  bool marchVariants = true;
  // One point sprite per glyph where every glyph's rectangle fits a point,
  // else two triangles (render/sprite_primitive.h; off only to measure).
  bool pointSprites = true;
  // Quads along a glyph's projected axes where smaller than its axis-aligned
  // rectangle (shaders/lib/sprite.glsl; off only to measure).
  bool orientedSprites = true;
  // On llvmpipe with small glyphs, a per-frame pass keeps only glyphs that a
  // pixel centre can see (render/glyph_culling.h; off only to measure).
  bool pixelCull = true;
  // > 0: draw the tessellated baseline at this resolution instead of ray
  // casting (superquadrics at `gamma`; render/tessellated.h).
  int tessellation = 0;
  ColorMode color = ColorMode::DEC;
  // A scalar mode's map; none: the quantity's own (render/color_scalar.h).
  std::optional<Colormap> colormap;
  // ColorMode::Array through the colours GlyphRenderer::setColorTable took
  // (a host's own map: ParaView's lookup table) instead of `colormap`.
  bool colorTable = false;
  // The values at the map's ends (sign: M = max(|lo|, |hi|) saturates);
  // none: the uploaded field's range (GlyphRenderer::colorWindow).
  std::optional<glm::dvec2> colorWindow;
  glm::vec4 background{0.08f, 0.08f, 0.10f, 1.0f};
  Lighting light;
  LegendParams legend;
  // R/L, A/P, S/I on the image's edges (render/legend/orientation_pass.h), at the
  // legend's text size; off: no pass of theirs is built, run or allocated.
  bool orientationLetters = false;
  AoParams ao;            // deferred depth cues: off by default, and then
  OutlineParams outline;  // no pass of theirs is built, run or allocated
  ShadowParams shadow;    // soft shadows from the key light (render/shadow_pass.h)
  bool operator==(const FrameParams&) const = default;
};

// How far a glyph of p's kind reaches from its centre, in its largest
// semi-axes: a box's corner (tensor::kGlyphReach) for every kind; a blob's
// bump to where it falls to its cutoff (shaders/lib/blob.glsl's
// blobBoundGauge) times that, since its surface may lie anywhere its bump
// still adds.
// The gauge (in glyph radii) where a bump falls to its cutoff, the C++ twin
// of shaders/lib/blob.glsl's blobBoundGauge: sqrt(1 + ln(C T) / B); 0 where
// its peak stays below C T.
inline double blobBoundGauge(const BlobParams& b) {
  const double s = 1.0 + std::log(b.cutoff * b.threshold) / b.blobbiness;
  return s > 0.0 ? std::sqrt(s) : 0.0;
}

inline double kindReach(const FrameParams& p) {
  if (p.glyph != GlyphKind::Blob) return tensor::kGlyphReach;
  return tensor::kGlyphReach * std::max(1.0, blobBoundGauge(p.blob));
}

// How far beyond tensor::glyphBoxWC (which holds kGlyphReach) a glyph of p's
// kind can reach, in world units, for glyphs of largest |eigenvalue|
// maxAbsEigenvalue: 0 but for blobs.
inline double kindPadWC(const FrameParams& p, double maxAbsEigenvalue) {
  return (kindReach(p) - tensor::kGlyphReach) * tensor::glyphRadiusWC(p.scale, p.sizing, maxAbsEigenvalue);
}

}  // namespace tg::render
