#pragma once
// The defaults a stress (or strain) field gets where the flags are silent:
// superquadric glyphs, whose shape shows the signs; the sign colour with its
// legend (orange tension, blue compression); and --magnitude log, so that the
// stress concentration stays the largest glyphs without the clamp flattening
// it (measured with the default clamp, share of glyphs shrunk, linear vs log:
// the kitten FEM field 2.9% vs 0.1%, the point load 16^3 3.3% vs 1.1%, the
// Kirsch plate 64^2 0.2% vs 0%). Explicit options always win.
#include <optional>
#include <string>
#include <vector>

#include "app/look_flags.h"
#include "io/field/tensor_field.h"
#include "tensor/field_stats.h"
#include "tensor/glyph_scale.h"

namespace tg::app {

struct StressDefaults {
  std::string why;  // "the tensor array is named \"stress\"", or the share that is not positive definite
};
// Whether `f` (its array's name) or its whole-field statistics say stress:
// an array named like stress or strain (stress, strain, sigma, epsilon,
// cauchy), or more than half of the non-zero tensors not positive definite
// (FieldStats::mostlyNotPositive: a DTI fit's few noisy voxels are not half).
std::optional<StressDefaults> stressDefaults(const io::TensorField& f, const tensor::FieldStats& s);
// The look of a stress field (superquadrics, the sign colour, a legend on
// images 480 rows high or more; no shadows or occlusion, as for other files).
SceneLook stressLook();
inline constexpr tensor::Magnitude kStressMagnitude = tensor::Magnitude::Log;
// One line for `info` and --verbose: what was chosen and why.
std::string stressDefaultsLine(const StressDefaults& d);

// The sign colour's automatic window is -M..M, M the field's largest
// |eigenvalue|, and stays so: the legend states it, and the concentration
// it came from keeps its full colour. Where that peak stands far above the
// body (a load point or fixed node: the kitten's 1030 against a 95th
// percentile of 64), nearly every glyph is drawn pale, so `render` says so
// in one line naming a window to fix (--color-range, at the percentile)
// and --color vonmises. "" where the peak is within kSignPeakRatio of the
// percentile. `sorted`: the whole field's magnitudes (tensor::MagnitudeSample).
inline constexpr double kSignHintPercentile = 0.95, kSignPeakRatio = 4.0;
std::string signWindowHint(double peak, const std::vector<double>& sorted, const std::string& units);

}  // namespace tg::app
