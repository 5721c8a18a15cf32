// What ParaView's own colour legend (a lookup table and its scalar bar)
// needs to show the glyphs' colours: the quantity a colour mode maps, the
// range the renderer maps onto its colormap, and that colormap as ParaView's
// RGBPoints (value, r, g, b per control point, linear in RGB between them).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "glyph_input.h"

namespace tg::paraview {

struct ColorLegend {
  std::string title;  // empty: the mode maps no scalar (DEC)
  double lo = 0, hi = 1;
  std::vector<std::array<double, 4>> points;  // value, r, g, b
};

// The legend of render::ColorMode `mode` over the whole dataset's `sizing`:
// FA, cl and cp map 0..1 and MD the glyphs' MD range onto viridis; sign maps
// the normalised normal stress -1..1 onto its diverging ramp
// (shaders/lib/color.glsl). DEC and unknown modes: no scalar, no points.
ColorLegend colorLegend(int mode, const SizingInfo& sizing);

}  // namespace tg::paraview
