#pragma once
// The deferred depth cues' command-line flags (render --ao --outlines and
// their parameters) and the range-checked parsers that the view script
// shares, so that both accept the same values. Defaults live in the
// parameter structs (render::AoParams, render::OutlineParams).
#include <span>
#include <string_view>

#include "app/option_table.h"
#include <glm/vec4.hpp>

#include "render/frame_params.h"

namespace tg::app {

// Each throws UsageError naming `flag` for a value out of range.
double parseAoRadius(std::string_view flag, std::string_view text);    // world units, > 0
double parseAoStrength(std::string_view flag, std::string_view text);  // 0..AoParams::kMaxStrength
int parseAoSamples(std::string_view flag, std::string_view text);      // AoParams::kMinSamples..kMaxSamples
double parseOutlineWidth(std::string_view flag, std::string_view text);  // pixels, 0.25..OutlineParams::kMaxWidth
double parseOutlineCrease(std::string_view flag, std::string_view text);  // degrees, 1..179
glm::vec4 parseOutlineColor(std::string_view flag, std::span<const char* const> rgba);  // 4 numbers, 0..1

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
