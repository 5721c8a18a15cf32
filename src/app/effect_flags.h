#pragma once
// The deferred depth cues' command-line flags (render --ao --outlines and
// their parameters); their ranges are app/scale/option_ranges.h's, which the view
// script shares. Defaults live in the parameter structs (render::AoParams,
// render::OutlineParams).
#include "app/scale/option_table.h"

#include "render/frame_params.h"

namespace tg::app {

struct EffectFlags {
  render::AoParams ao;
  render::OutlineParams outline;
  bool aoTuned = false, outlineTuned = false;  // a parameter flag was given

  // --ao --ao-radius --ao-strength --ao-samples --outlines --outline-width
  // --outline-color --outline-crease
  void addTo(OptionTable& ap);
  // A parameter flag without its effect's switch is a usage error: it would
  // silently do nothing.
  void validate() const;
};

}  // namespace tg::app
