#pragma once
// The legend's flags, shared by render and view: --legend, --legend-corner,
// --units, --length-units, --legend-text-scale (render::LegendParams).
#include <optional>
#include <string>
#include <string_view>

#include "app/scale/option_table.h"

#include "render/legend_params.h"

namespace tg::app {

inline constexpr const char* kLegendCornerNames = "top-left, top-right, bottom-left or bottom-right";

std::optional<render::LegendCorner> legendCornerNamed(std::string_view name);
const char* legendCornerName(render::LegendCorner c);

// Throws UsageError "FLAG: ..." for text the legend cannot show: control
// characters, or longer than 40 bytes (the panel would outgrow the image).
void checkLegendText(std::string_view flag, std::string_view text);

struct LegendFlags {
  render::LegendParams params;
  bool detailGiven = false;  // any legend flag other than --legend

  void addTo(OptionTable& ap);
  // Throws UsageError; called before anything is loaded.
  void validate() const;
};

}  // namespace tg::app
