#pragma once
// How big each glyph is drawn, and what the default camera frames: the one
// home of the scale parameters and their defaults, read by the CLI (render,
// info, view), the viewer's panel and script, and later Python.
//
// A glyph's size is its eigenvalues times one factor k of its own, so the
// magnitude mapping and the clamp never change its shape ratios (as
// vtkTensorGlyph's ClampScaling, and as stress-glyph users map magnitudes):
//   m = max |λ_i|,  k = S · f(m) / m,  then k ← min(k, R / m) with the clamp R,
// f the magnitude mapping. Signs stay with the eigenvalues (colour, shape).
// Everything here is a uniform on the GPU (shaders/lib/glyph_size.glsl):
// changing it never re-uploads.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "tensor/field_stats.h"
#include "tensor/glyph.h"

namespace tg::tensor {

// How a glyph's largest |eigenvalue| m becomes its drawn size f(m):
//   Linear: m (the eigenvalues as they are);
//   Log:    λ0 · ln(1 + m / λ0): linear below λ0, logarithmic above, so a
//           singular load's glyphs do not dwarf the rest;
//   Shape:  λ0 for every glyph: shape only, every glyph the same size.
enum class Magnitude { Linear = 0, Log = 1, Shape = 2 };
inline constexpr const char* kMagnitudeNames = "linear, log or shape";
std::optional<Magnitude> magnitudeNamed(const std::string& name);
const char* magnitudeName(Magnitude m);

// The mapping and the clamp as the shaders get them (with FrameParams::scale).
struct SizeMapping {
  Magnitude magnitude = Magnitude::Linear;
  double lambda0 = 1.0;      // eigenvalue units: the log knee, or shape's fixed size
  double maxRadiusWC = 0.0;  // the clamp on a glyph's largest semi-axis; 0: none
  bool operator==(const SizeMapping&) const = default;
};

// f(m) above; 0 for m = 0.
double mappedMagnitude(const SizeMapping& s, double m);
// World units per eigenvalue unit of a glyph whose largest |eigenvalue| is m,
// at `scale` world units per mapped unit: exactly `scale` when the mapping is
// linear and the clamp does not bite (today's glyphs, bit for bit).
double glyphFactor(double scale, const SizeMapping& s, double m);
// The largest semi-axis of such a glyph (non-decreasing in m).
inline double glyphRadiusWC(double scale, const SizeMapping& s, double m) { return glyphFactor(scale, s, m) * m; }
// ellipsoidAxes at the glyph's own factor.
glm::dvec3 glyphAxes(const GlyphRecord& g, double scale, const SizeMapping& s);

// What the user chooses (render/view/info flags, viewer, script).
struct ScaleParams {
  // absolute: `factor` world units of diameter per (mapped) eigenvalue unit,
  // as ParaView's TensorGlyph ScaleFactor (Teem's tend glyph -gsc, a
  // semi-axis, is factor / 2);
  // max: the largest glyph is `factor` sample spacings across;
  // spacing: the glyph at the `percentile` of sizes (of the non-zero tensors)
  // is `factor` spacings across.
  ScaleMode mode = ScaleMode::Spacing;
  double factor = 1.0;
  // 0.9, not the maximum nor 0.99: in a singular field (a point load) the top
  // percent are the load's neighbours, and sizing by them left every other
  // glyph a dot (docs/guide.md, "Scale and framing"; measured there).
  double percentile = 0.9;
  Magnitude magnitude = Magnitude::Linear;
  std::optional<double> lambda0;  // default: the median non-zero glyph magnitude m
  // Largest glyph diameter, in sample spacings (vtkTensorGlyph's ClampScaling,
  // MaxScaleFactor in spacings); 0: off. Default: kDefaultClamp in the
  // spacing and max modes, off in absolute mode (a size in world units is
  // taken as given, as ParaView does with clamping off).
  std::optional<double> clampSpacings;
  static constexpr double kDefaultClamp = 2.0;
  bool operator==(const ScaleParams&) const = default;
};

// The glyphs' non-zero magnitudes m (all of them up to 65536, else the
// FieldStats sketch's uniform sample), sorted, and what resolution needs
// besides: computed once, so that the viewer resolves any ScaleParams after
// the records have gone to the GPU.
struct MagnitudeSample {
  std::vector<double> sorted;
  double maxAbs = 0;
  double spacing = 0;  // the field's sample spacing
  std::string from;    // where the ranges come from, for the why line ("" : not said)
};
MagnitudeSample magnitudeSample(const FieldStats& stats, double sampleSpacing, std::string from = {});
MagnitudeSample sampleMagnitudes(const GlyphSet& set, double sampleSpacing);

struct ResolvedScale {
  double scale = 1.0;  // FrameParams::scale
  SizeMapping mapping;
  double clampedFraction = 0;  // of the sample, glyphs the clamp shrinks
  double typicalRadiusWC = 0;  // the radius of the glyph at the percentile: framing's margin
  std::string why;             // one line for --verbose and info
};
ResolvedScale resolveScale(const ScaleParams& p, const MagnitudeSample& sample);
// The value at fraction q of a sorted sample (nearest rank); 0 for none.
double quantile(const std::vector<double>& sorted, double q);

// The default ScaleParams' scale: the glyph at the 90th percentile of sizes
// is one sample spacing across. 1 when undefined.
double defaultScale(const GlyphSet& set, double sampleSpacing);

// The largest semi-axis any glyph of the set has (the mapping is monotonic,
// so it is the one of the largest magnitude).
inline double maxGlyphRadiusWC(const GlyphSet& set, double scale, const SizeMapping& s) {
  return glyphRadiusWC(scale, s, set.maxAbsEigenvalue);
}
// glyphBoxWC for mapped and clamped glyphs: the depth range and culling box.
BoxWC glyphBoxWC(const GlyphSet& set, double scale, const SizeMapping& s);

// What the default camera frames: the sample positions, not the glyphs grown
// by their largest one; where some tensors are zero (a DTI volume's
// background), only the positions of those that are not. Their bounds; for
// scattered points (no grid) whose
// bounds are more than kOutlierSpread times the 0.5..99.5 percentile box on
// an axis, that box. Either grown by `padWC` (a typical glyph's radius).
struct FramingBox {
  glm::dvec3 lo{0.0}, hi{0.0};
  std::string why;
};
inline constexpr double kOutlierSpread = 1.25;
FramingBox framingBox(const GlyphSet& set, bool scattered, double padWC);

}  // namespace tg::tensor
