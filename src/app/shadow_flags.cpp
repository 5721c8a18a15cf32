#include "app/shadow_flags.h"

#include <cstdio>

#include "app/cli_values.h"

namespace tg::app {
void ShadowFlags::addTo(OptionTable& ap) {
  using Args = OptionArgs;
  const render::ShadowParams d;
  render::ShadowParams& p = params;
  auto given = [this](const char* flag) {
    if (firstParameterFlag.empty()) firstParameterFlag = flag;
  };
  ap.arg("--shadows").help("soft shadows from the key light (percentage-closer filtered shadow map)")
      .action([&p](Args) { p.enabled = true; });
  ap.arg("--shadow-penumbra F")
      .help("width of the shadows' soft edge, as a fraction of the shadowed region's width (0.." +
            formatNumber(render::kMaxShadowPenumbra) + ", default " + formatNumber(d.penumbra) + ")")
      .action([&p, given](Args a) {
        given("--shadow-penumbra");
        p.penumbra = float(parseDoubleIn("--shadow-penumbra", a[1], 0.0, render::kMaxShadowPenumbra));
      });
  ap.arg("--shadow-map-size N")
      .help("shadow map texels per side, fixed (" + formatNumber(render::kMinShadowMapSize) + ".." +
            formatNumber(render::kMaxShadowMapSize) + "; default: about " + formatNumber(d.mapDensity) +
            " per image pixel at the glyphs, at most " + formatNumber(d.mapSize) + ")")
      .action([&p, given](Args a) {
        given("--shadow-map-size");
        p.mapSize = parseIntIn("--shadow-map-size", a[1], render::kMinShadowMapSize, render::kMaxShadowMapSize);
        p.mapDensity = 0.0f;
      });
  ap.arg("--shadow-strength S")
      .help("share of the key light a full shadow removes (0..1, default " + formatNumber(d.strength) + ")")
      .action([&p, given](Args a) {
        given("--shadow-strength");
        p.strength = float(parseDoubleIn("--shadow-strength", a[1], 0.0, 1.0));
      });
  ap.arg("--shadow-bias B")
      .help("depth bias along the light, in shadow map texels (0.." + formatNumber(render::kMaxShadowBias) + ", default " +
            formatNumber(d.bias) + ")")
      .action([&p, given](Args a) {
        given("--shadow-bias");
        p.bias = float(parseDoubleIn("--shadow-bias", a[1], 0.0, render::kMaxShadowBias));
      });
}

void ShadowFlags::validate() const {
  if (!firstParameterFlag.empty() && !params.enabled) throw UsageError(firstParameterFlag + " needs --shadows");
}

}  // namespace tg::app
