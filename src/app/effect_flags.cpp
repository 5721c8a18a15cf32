#include "app/effect_flags.h"

#include <cmath>
#include <sstream>
#include <string>

#include "app/scale/cli_values.h"
#include "app/scale/option_ranges.h"
#include "tensor/glyph_scale.h"

namespace tg::app {
void EffectFlags::addTo(OptionTable& ap) {
  using Args = OptionArgs;
  const render::AoParams a;
  const render::OutlineParams o;
  const std::string group = ap.groupDefault();
  ap.setGroup("depth cues");
  ap.arg("--ao").help("screen-space ambient occlusion: glyphs in a dense field darken each other").action([&](Args) {
    ao.enabled = true;
  });
  std::ostringstream autoRadius;
  autoRadius << "occlusion radius in world units (default: " << render::AoParams::kAutoRadius
             << " typical glyph diameter, the " << std::lround(100 * tensor::ScaleParams{}.percentile) << "th"
             << "-percentile glyph's)";
  ap.arg("--ao-radius R").help(autoRadius.str()).range(ranges::kPositiveFloat)
      .action([&](Args v) {
        ao.radius = parseDouble(v[0], v[1]);
        aoTuned = true;
      });
  ap.arg("--ao-strength S").help("occlusion weight; 1 takes all ambient and head light from a fully occluded point")
      .range(ranges::kAoStrength).byDefault(formatNumber(a.strength)).action([&](Args v) {
        ao.strength = parseDouble(v[0], v[1]);
        aoTuned = true;
      });
  ap.arg("--ao-samples N").help("hemisphere samples per pixel").range(ranges::kAoSamples)
      .byDefault(formatNumber(a.samples))
      .action([&](Args v) {
    ao.samples = int(parseInt(v[0], v[1]));
    aoTuned = true;
  });
  ap.arg("--outlines").help("silhouette and crease lines where glyph, depth or normal change").action([&](Args) {
    outline.enabled = true;
  });
  ap.arg("--outline-width W").help("line width in pixels").range(ranges::kOutlineWidth)
      .byDefault(formatNumber(o.width))
      .action([&](Args v) {
    outline.width = parseDouble(v[0], v[1]);
    outlineTuned = true;
  });
  ap.arg("--outline-color R G B A").help("line colour; A blends").range(ranges::kUnit)
      .byDefault(formatNumber(o.color.r) + " " + formatNumber(o.color.g) + " " + formatNumber(o.color.b) + " " +
                 formatNumber(o.color.a))
      .action([&](Args v) {
    for (int k = 0; k < 4; ++k) outline.color[k] = float(parseDouble(v[0], v[1 + k]));
    outlineTuned = true;
  });
  ap.arg("--outline-crease DEG").help("normals turning more than this draw a crease line")
      .range(ranges::kCreaseDeg).byDefault(formatNumber(o.creaseDeg)).action([&](Args v) {
        outline.creaseDeg = parseDouble(v[0], v[1]);
        outlineTuned = true;
      });
  ap.setGroup(group);
}

void EffectFlags::validate() const {
  if (aoTuned && !ao.enabled) throw UsageError("--ao-radius, --ao-strength and --ao-samples need --ao");
  if (outlineTuned && !outline.enabled)
    throw UsageError("--outline-width, --outline-color and --outline-crease need --outlines");
}

}  // namespace tg::app
