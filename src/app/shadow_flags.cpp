#include "app/shadow_flags.h"

#include <cstdio>

#include "app/scale/cli_values.h"
#include "app/scale/option_ranges.h"

namespace tg::app {
void ShadowFlags::addTo(OptionTable& ap) {
  using Args = OptionArgs;
  const render::ShadowParams d;
  render::ShadowParams& p = params;
  auto given = [this](const char* flag) {
    if (firstParameterFlag.empty()) firstParameterFlag = flag;
  };
  const std::string group = ap.groupDefault();
  ap.setGroup("depth cues");
  ap.arg("--shadows").help("soft shadows from the key light (percentage-closer filtered shadow map)")
      .action([&p](Args) { p.enabled = true; });
  ap.arg("--shadow-penumbra F")
      .help("width of the shadows' soft edge, as a fraction of the shadowed region's width")
      .range(ranges::kShadowPenumbra).byDefault(formatNumber(d.penumbra)).action([&p, given](Args a) {
        given("--shadow-penumbra");
        p.penumbra = float(parseDouble(a[0], a[1]));
      });
  ap.arg("--shadow-map-size N")
      .help("shadow map texels per side, fixed (default: about " + formatNumber(d.mapDensity) +
            " per image pixel at the glyphs, at most " + formatNumber(d.mapSize) + ")")
      .range(ranges::kShadowMapSize).action([&p, given](Args a) {
        given("--shadow-map-size");
        p.mapSize = int(parseInt(a[0], a[1]));
        p.mapDensity = 0.0f;
      });
  ap.arg("--shadow-strength S")
      .help("share of the key light a full shadow removes")
      .range(ranges::kUnit).byDefault(formatNumber(d.strength)).action([&p, given](Args a) {
        given("--shadow-strength");
        p.strength = float(parseDouble(a[0], a[1]));
      });
  ap.arg("--shadow-bias B")
      .help("depth bias along the light, in shadow map texels")
      .range(ranges::kShadowBias).byDefault(formatNumber(d.bias)).action([&p, given](Args a) {
        given("--shadow-bias");
        p.bias = float(parseDouble(a[0], a[1]));
      });
  ap.setGroup(group);
}

void ShadowFlags::validate() const {
  if (!firstParameterFlag.empty() && !params.enabled) throw UsageError(firstParameterFlag + " needs --shadows");
}

}  // namespace tg::app
