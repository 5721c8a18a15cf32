#pragma once
// The range of every numeric option, declared once and read by every surface
// that takes the value: the command lines' option tables (render, view, info,
// bench), the view script and its panel, and the Python keywords (through the
// tables). A value outside is refused with one wording, rangeMessage().
//
// The renderer works in single precision: a value it would turn into 0, a
// denormal or infinity (a uniform) has no picture, so a range never reaches
// beyond kFloatMin..kFloatMax, and a positive quantity starts at kFloatMin.
#include <string>
#include <string_view>

#include "app/scale/frame_size.h"
#include "render/ao_pass.h"
#include "render/legend_params.h"
#include "render/outline_pass.h"
#include "render/shadow_pass.h"
#include "render/tessellated.h"

namespace tg::app {

struct NumberRange {
  double lo = 0, hi = 0;
  bool integer = false;
  bool zeroOff = false;  // 0 is accepted too, meaning "off", though below lo
  bool contains(double v) const { return (v >= lo && v <= hi) || (zeroOff && v == 0.0); }
  // "0..10000", "0 (off) or 4..64": what the messages, --help and docs/cli.md show.
  std::string text() const;
};

// "NAME must be within RANGE": the one wording for a value out of range.
std::string rangeMessage(std::string_view name, const NumberRange& r);
// Parses `text` strictly (parseDouble, or parseInt for an integer range) and
// checks it against `r`; throws UsageError naming `name`.
double checkedNumber(std::string_view name, std::string_view text, const NumberRange& r);

// Normal single-precision magnitudes, rounded inwards to short numbers.
inline constexpr double kFloatMin = 1.2e-38, kFloatMax = 3.4e38;

namespace ranges {
inline constexpr NumberRange kAnyFloat{-kFloatMax, kFloatMax};
inline constexpr NumberRange kPositiveFloat{kFloatMin, kFloatMax};
inline constexpr NumberRange kUnit{0.0, 1.0};
inline constexpr NumberRange kGamma{0.0, 1e4};
inline constexpr NumberRange kIterations{1, 1000, true};
inline constexpr NumberRange kEpsilon{1e-9, 0.5};
// Blobs (render::BlobParams): a threshold and a bump's height exp(-B) both
// within what single precision holds with room; a cutoff small enough that
// truncation stays below the threshold, large enough that a bump's region
// (sqrt(1 + ln(t T) / B) glyph radii) stays finite.
inline constexpr NumberRange kBlobThreshold{1e-6, 1e6};
// Below -16 the bump's exp(-B) peak leaves float too little room for its
// gradient's shading (banded highlights were seen at -40).
inline constexpr NumberRange kBlobbiness{-16.0, -0.01};
inline constexpr NumberRange kBlobCutoff{1e-9, 0.5};
inline constexpr NumberRange kBlobSteps{1, 64, true};
inline constexpr NumberRange kSamples{1, 16, true};  // colour samples at a silhouette pixel (render::AntialiasPass)
// Below 0.01 degrees a pixel is finer than single precision resolves at the
// scene (app/render_options.cpp checks the exact bound for the image height);
// above 179 the scene shrinks towards a point.
inline constexpr NumberRange kFovDeg{0.01, 179.0};
// The benchmarks' images: at least 16 pixels a side, at most 8192.
inline constexpr NumberRange kBenchFrameSide{16, 8192, true};
inline constexpr NumberRange kStride{1, 1000000, true};
// 0 is off; below 0.01 sample spacings no glyph covers a pixel.
inline constexpr NumberRange kClampSpacings{0.01, 1e6, false, true};
inline constexpr NumberRange kRepeat{0, 10000, true};
inline constexpr NumberRange kFrames{1, 1000, true};
inline constexpr NumberRange kRepeats{1, 100, true};
// The view script: frames to wait, and a pixel of the window to pick.
inline constexpr NumberRange kScriptFrames{1, 100000, true};
inline constexpr NumberRange kPixelIndex{0, kMaxFrameSide - 1, true};
inline constexpr NumberRange kPercent{0.0, 100.0};
inline constexpr NumberRange kPlaneOffsetRadii{0.0, 100.0};
inline constexpr NumberRange kFeatureAngleDeg{0.0, 180.0};
inline constexpr NumberRange kTractWidth{1e-9, 1e9};  // world units: a tube wider than any scene is a mistake
inline constexpr NumberRange kCreaseDeg{1.0, 179.0};
inline constexpr NumberRange kTessellation{render::TessellatedGlyphs::kMinResolution,
                                          render::TessellatedGlyphs::kMaxResolution, true, true};
inline constexpr NumberRange kAoStrength{0.0, render::AoParams::kMaxStrength};
inline constexpr NumberRange kAoSamples{render::AoParams::kMinSamples, render::AoParams::kMaxSamples, true};
inline constexpr NumberRange kOutlineWidth{0.25, render::OutlineParams::kMaxWidth};
inline constexpr NumberRange kShadowPenumbra{0.0, render::kMaxShadowPenumbra};
inline constexpr NumberRange kShadowMapSize{render::kMinShadowMapSize, render::kMaxShadowMapSize, true};
inline constexpr NumberRange kShadowBias{0.0, render::kMaxShadowBias};
inline constexpr NumberRange kLegendTextScale{1, render::kMaxLegendTextScale, true};
// The view script's lights (render::LightParams): intensities, and the
// specular exponent.
inline constexpr NumberRange kLight{0.0, 1.0};
inline constexpr NumberRange kShininess{1.0, 1000.0};
}  // namespace ranges

}  // namespace tg::app
