#include "app/look_flags.h"

#include <string>

#include "app/scale/cli_values.h"

namespace tg::app {

void LookFlags::addTo(OptionTable& ap) {
  using Args = OptionArgs;
  const std::string group = ap.groupDefault();
  ap.setGroup("depth cues");
  ap.arg("--no-shadows").help("the built-in scene without its shadows").action([this](Args) { noShadows = true; });
  ap.arg("--no-ao").help("... without its ambient occlusion").action([this](Args) { noAo = true; });
  ap.arg("--no-legend").help("... without its legend").action([this](Args) { noLegend = true; });
  // The scene's look leaves outlines off (SceneLook), so this flag only
  // states the default; it stays for scripts that pass every --no-* flag.
  ap.arg("--no-outlines")
      .help("no outlines: the default for every input, the built-in scene included (refused with --outlines)")
      .action([this](Args) { noOutlines = true; });
  ap.setGroup(group);
}

void LookFlags::validate(bool shadows, bool ao, bool outlines, bool legend) const {
  const struct {
    bool on, off;
    const char* name;
  } effects[] = {{shadows, noShadows, "shadows"}, {ao, noAo, "ao"}, {outlines, noOutlines, "outlines"},
                 {legend, noLegend, "legend"}};
  for (const auto& e : effects)
    if (e.on && e.off) throw UsageError(std::string("--") + e.name + " and --no-" + e.name + " exclude each other");
}

void LookFlags::apply(const SceneLook& look, render::FrameParams& p, int imageHeight) const {
  if (!glyphGiven) p.glyph = look.glyph;
  if (!colorGiven && look.color) p.color = *look.color;
  p.shadow.enabled = p.shadow.enabled || (look.shadows && !noShadows);
  p.ao.enabled = p.ao.enabled || (look.ao && !noAo);
  p.outline.enabled = p.outline.enabled || (look.outlines && !noOutlines);
  p.legend.enabled = p.legend.enabled || (look.legend && !noLegend && imageHeight >= look.legendMinHeight);
}

}  // namespace tg::app
