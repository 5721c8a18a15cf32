#pragma once
// What the legend shows (render/legend/legend_pass.h draws it): one struct for the
// CLI (`render --legend`), the viewer's panel and script, and later Python.
#include <string>

namespace tg::render {

enum class LegendCorner { TopLeft, TopRight, BottomLeft, BottomRight };

struct LegendParams {
  bool enabled = false;  // off: no legend pass is built, run or allocated
  LegendCorner corner = LegendCorner::BottomRight;
  // The colour key: a bar for fa, md, cl, cp and sign; a sphere of the
  // directional colours for dec.
  bool colorKey = true;
  bool scaleBar = true;  // a round world length at the look-at point's depth
  std::string units;        // of the tensor values, e.g. "MPa" or "mm^2/s"
  std::string lengthUnits;  // of positions, e.g. "mm"; empty: "world units"
  // Text height as a multiple of the 13-pixel font (integer, so that the
  // pixel font stays sharp); 0: one per 512 image rows, at least 1.
  int textScale = 0;
  bool operator==(const LegendParams&) const = default;
};

inline constexpr int kMaxLegendTextScale = 8;

}  // namespace tg::render
