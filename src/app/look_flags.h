#pragma once
// The built-in scene's look: superquadrics with shadows, occlusion and a
// legend, what the product shows first (Scene::preferredLook). It
// applies where the command line is silent; --glyph chooses the kind, and
// --no-shadows, --no-ao, --no-outlines and --no-legend turn an effect off.
// A field read from a file has no preferred look: every effect is off unless
// asked for (docs/guide.md, "Depth cues and legends", says why), but for a
// stress field's (app/stress_defaults.h).
#include <optional>

#include "app/scale/option_table.h"

#include "render/frame_params.h"

namespace tg::app {

// Outlines stay off: on glyphs a few pixels wide (this scene below about
// 800 pixels) their lines cover the glyphs. The legend needs room: its text
// is whole multiples of a 13-pixel font, so on a small image it would cover
// the scene.
struct SceneLook {
  render::GlyphKind glyph = render::GlyphKind::Superquadric;
  bool shadows = true, ao = true, outlines = false, legend = true;
  int legendMinHeight = 480;  // pixels
  std::optional<render::ColorMode> color;  // where --color is silent; none: the option's default
};

struct LookFlags {
  bool glyphGiven = false;  // set by the command's own --glyph action
  bool colorGiven = false;  // and --color's
  bool noShadows = false, noAo = false, noOutlines = false, noLegend = false;

  void addTo(OptionTable& ap);
  // UsageError for an effect both asked for and refused (--ao --no-ao).
  void validate(bool shadows, bool ao, bool outlines, bool legend) const;
  // `p` holds what the flags asked for; the look fills in the rest for an
  // image `imageHeight` pixels high.
  void apply(const SceneLook& look, render::FrameParams& p, int imageHeight) const;
};

}  // namespace tg::app
