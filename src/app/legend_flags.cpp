#include "app/legend_flags.h"

#include "app/scale/cli_values.h"
#include "app/scale/option_ranges.h"

namespace tg::app {

std::optional<render::LegendCorner> legendCornerNamed(std::string_view name) {
  using C = render::LegendCorner;
  if (name == "top-left") return C::TopLeft;
  if (name == "top-right") return C::TopRight;
  if (name == "bottom-left") return C::BottomLeft;
  if (name == "bottom-right") return C::BottomRight;
  return std::nullopt;
}

const char* legendCornerName(render::LegendCorner c) {
  using C = render::LegendCorner;
  return c == C::TopLeft ? "top-left" : c == C::TopRight ? "top-right" : c == C::BottomLeft ? "bottom-left" : "bottom-right";
}

void checkLegendText(std::string_view flag, std::string_view text) {
  if (text.size() > 40) throw UsageError(std::string(flag) + ": at most 40 characters");
  for (const char c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      throw UsageError(std::string(flag) + ": control characters cannot be shown");
}

void LegendFlags::addTo(OptionTable& ap) {
  using Args = OptionArgs;
  const std::string group = ap.groupDefault();
  ap.setGroup("colour");
  ap.arg("--legend").help("draw a legend: the colour key (a bar, or for dec a sphere of directions) and a scale bar")
      .action([this](Args) { params.enabled = true; });
  ap.arg("--legend-corner C").help(std::string("the legend's corner: ") + kLegendCornerNames).oneOf(kLegendCornerNames)
      .byDefault(legendCornerName(render::LegendParams{}.corner))
      .action([this](Args a) {
        const auto c = legendCornerNamed(a[1]);
        if (!c) throw UsageError(std::string("--legend-corner: unknown corner \"") + a[1] + "\"; choose " +
                                 kLegendCornerNames);
        params.corner = *c;
        detailGiven = true;
      });
  ap.arg("--units TEXT").help("units of the tensor values in the legend, e.g. MPa or mm^2/s (default none)")
      .action([this](Args a) {
        params.units = a[1];
        detailGiven = true;
      });
  ap.arg("--length-units TEXT").help("units of positions for the scale bar, e.g. mm (default: the file's, from "
                                     "NIfTI xyzt_units or NRRD space units, else \"world units\")")
      .action([this](Args a) {
        params.lengthUnits = a[1];
        detailGiven = true;
      });
  ap.arg("--legend-text-scale K").help("legend text height, K x 13 pixels (default: 1 per 700 image rows)")
      .range(ranges::kLegendTextScale).action([this](Args a) {
        params.textScale = int(parseInt(a[0], a[1]));
        detailGiven = true;
      });
  ap.setGroup(group);
}

void LegendFlags::validate() const {
  if (detailGiven && !params.enabled)
    throw UsageError("--legend-corner, --units, --length-units and --legend-text-scale need --legend");
  checkLegendText("--units", params.units);
  checkLegendText("--length-units", params.lengthUnits);
}

}  // namespace tg::app
