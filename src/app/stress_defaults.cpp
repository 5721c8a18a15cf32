#include "app/stress_defaults.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace tg::app {

std::optional<StressDefaults> stressDefaults(const io::TensorField& f, const tensor::FieldStats& s) {
  std::string name = f.arrayName;
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  for (const char* word : {"stress", "strain", "sigma", "epsilon", "cauchy"})
    if (name.find(word) != std::string::npos) return StressDefaults{"the tensor array is named \"" + f.arrayName + "\""};
  if (s.mostlyNotPositive())
    return StressDefaults{std::to_string(std::lround(100.0 * double(s.notPositive) / double(s.nonZero))) +
                          "% of the non-zero tensors are not positive definite (compression, or a zero principal "
                          "value), as no diffusion tensor is"};
  return std::nullopt;
}

SceneLook stressLook() {
  SceneLook look;
  look.glyph = render::GlyphKind::Superquadric;
  look.shadows = look.ao = look.outlines = false;
  look.legend = true;
  look.color = render::ColorMode::Sign;
  return look;
}

std::string stressDefaultsLine(const StressDefaults& d) {
  return "stress defaults (" + d.why + "): superquadric glyphs, --color sign with a legend, --magnitude log; " +
         "--glyph, --color, --no-legend and --magnitude override them";
}

std::string signWindowHint(double peak, const std::vector<double>& sorted, const std::string& units) {
  const double typical = tensor::quantile(sorted, kSignHintPercentile);
  if (!(typical > 0.0) || !(peak > kSignPeakRatio * typical)) return {};
  char buf[400];
  const std::string unit = units.empty() ? "" : " " + units;
  std::snprintf(buf, sizeof buf,
                "--color sign: the window is the peak |normal stress| %.4g%s, %.0fx the %.0fth percentile %.3g, so "
                "most glyphs are drawn nearly white; --color-range %.3g %.3g colours them (stronger ones then "
                "saturate), or --color vonmises",
                peak, unit.c_str(), peak / typical, 100.0 * kSignHintPercentile, typical, -typical, typical);
  return buf;
}

}  // namespace tg::app
