#include "app/effect_flags.h"

#include <cmath>
#include <sstream>
#include <string>

#include "app/cli_values.h"
#include "tensor/glyph_scale.h"

namespace tg::app {
namespace {

template <class T>
std::string withDefault(const char* text, T value) {
  std::ostringstream s;
  s << text << " (default " << value << ")";
  return s.str();
}

}  // namespace

double parseAoRadius(std::string_view flag, std::string_view text) {
  const double r = parseDouble(flag, text);
  if (!(r > 0.0)) throw UsageError(std::string(flag) + " must be positive (world units)");
  return r;
}

double parseAoStrength(std::string_view flag, std::string_view text) {
  return parseDoubleIn(flag, text, 0.0, render::AoParams::kMaxStrength);
}

int parseAoSamples(std::string_view flag, std::string_view text) {
  return parseIntIn(flag, text, render::AoParams::kMinSamples, render::AoParams::kMaxSamples);
}

double parseOutlineWidth(std::string_view flag, std::string_view text) {
  return parseDoubleIn(flag, text, 0.25, render::OutlineParams::kMaxWidth);
}

double parseOutlineCrease(std::string_view flag, std::string_view text) { return parseDoubleIn(flag, text, 1.0, 179.0); }

glm::vec4 parseOutlineColor(std::string_view flag, std::span<const char* const> rgba) {
  if (rgba.size() != 4) throw UsageError(std::string(flag) + " needs 4 numbers (R G B A)");
  glm::vec4 c;
  for (int k = 0; k < 4; ++k) c[k] = float(parseDoubleIn(flag, rgba[std::size_t(k)], 0.0, 1.0));
  return c;
}

void EffectFlags::addTo(OptionTable& ap) {
  using Args = OptionArgs;
  const render::AoParams a;
  const render::OutlineParams o;
  ap.arg("--ao").help("screen-space ambient occlusion: glyphs in a dense field darken each other").action([&](Args) {
    ao.enabled = true;
  });
  std::ostringstream autoRadius;
  autoRadius << "occlusion radius in world units (default: " << render::AoParams::kAutoRadius
             << " typical glyph diameter, the " << std::lround(100 * tensor::ScaleParams{}.percentile) << "th"
             << "-percentile glyph's)";
  ap.arg("--ao-radius R").help(autoRadius.str())
      .action([&](Args v) {
        ao.radius = parseAoRadius("--ao-radius", v[1]);
        aoTuned = true;
      });
  ap.arg("--ao-strength S").help(withDefault("occlusion weight, 0..4; 1 takes all ambient and head light from a fully "
                                             "occluded point", a.strength))
      .action([&](Args v) {
        ao.strength = parseAoStrength("--ao-strength", v[1]);
        aoTuned = true;
      });
  ap.arg("--ao-samples N").help(withDefault("hemisphere samples per pixel, 4..64", a.samples)).action([&](Args v) {
    ao.samples = parseAoSamples("--ao-samples", v[1]);
    aoTuned = true;
  });
  ap.arg("--outlines").help("silhouette and crease lines where glyph, depth or normal change").action([&](Args) {
    outline.enabled = true;
  });
  ap.arg("--outline-width W").help(withDefault("line width in pixels, 0.25..8", o.width)).action([&](Args v) {
    outline.width = parseOutlineWidth("--outline-width", v[1]);
    outlineTuned = true;
  });
  ap.arg("--outline-color R G B A").help("line colour, 0..1; A blends (default 0 0 0 1)").action([&](Args v) {
    outline.color = parseOutlineColor("--outline-color", std::span<const char* const>(v.data() + 1, 4));
    outlineTuned = true;
  });
  ap.arg("--outline-crease DEG").help(withDefault("normals turning more than this draw a crease line, 1..179", o.creaseDeg))
      .action([&](Args v) {
        outline.creaseDeg = parseOutlineCrease("--outline-crease", v[1]);
        outlineTuned = true;
      });
}

void EffectFlags::validate() const {
  if (aoTuned && !ao.enabled) throw UsageError("--ao-radius, --ao-strength and --ao-samples need --ao");
  if (outlineTuned && !outline.enabled)
    throw UsageError("--outline-width, --outline-color and --outline-crease need --outlines");
}

}  // namespace tg::app
