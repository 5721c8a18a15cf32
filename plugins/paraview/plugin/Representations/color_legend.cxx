#include "color_legend.h"

#include <cmath>

namespace tg::paraview {
namespace {

// The knots of viridis() and signRamp() in shaders/lib/color.glsl, which
// interpolate linearly in RGB between them as ParaView's lookup table does
// (test_paraview compares ParaView's scalar bar with that file).
constexpr std::array<std::array<double, 3>, 9> kViridis = {{{0.267, 0.005, 0.329},
                                                            {0.278, 0.175, 0.483},
                                                            {0.230, 0.322, 0.546},
                                                            {0.173, 0.449, 0.558},
                                                            {0.128, 0.567, 0.551},
                                                            {0.153, 0.680, 0.504},
                                                            {0.362, 0.786, 0.388},
                                                            {0.678, 0.864, 0.190},
                                                            {0.993, 0.906, 0.144}}};
constexpr std::array<double, 3> kCompression = {0.15, 0.40, 0.90}, kZero = {1.0, 1.0, 1.0},
                                kTension = {0.90, 0.42, 0.10};

}  // namespace

ColorLegend colorLegend(int mode, const SizingInfo& sizing) {
  ColorLegend legend;
  switch (mode) {
    case 1: legend.title = "FA (tensor glyphs)"; break;
    case 2: legend.title = "MD (tensor glyphs)"; break;
    case 3: legend.title = "cl (tensor glyphs)"; break;
    case 4: legend.title = "cp (tensor glyphs)"; break;
    case 5: legend.title = "normal stress / max |eigenvalue| (tensor glyphs)"; break;
    default: return legend;
  }
  if (mode == 2 && !(std::isfinite(sizing.mdMin) && std::isfinite(sizing.mdMax))) return legend;  // no glyphs
  if (mode == 5) {
    legend.lo = -1.0;
    legend.hi = 1.0;
    for (const auto& [v, c] : {std::pair{-1.0, kCompression}, std::pair{0.0, kZero}, std::pair{1.0, kTension}})
      legend.points.push_back({v, c[0], c[1], c[2]});
    return legend;
  }
  if (mode == 2) {
    // The shader maps MD over [mdMin, mdMax]; a field of one MD is all
    // viridis(0.5), the middle of any range around it.
    legend.lo = sizing.mdMin;
    legend.hi = sizing.mdMax;
    if (!(legend.hi > legend.lo)) {
      const double half = sizing.mdMin != 0.0 ? 0.01 * std::abs(sizing.mdMin) : 0.5;
      legend.lo = sizing.mdMin - half;
      legend.hi = sizing.mdMin + half;
    }
  }
  for (std::size_t k = 0; k < kViridis.size(); ++k) {
    const double t = double(k) / double(kViridis.size() - 1);
    const double v = k + 1 == kViridis.size() ? legend.hi : legend.lo + t * (legend.hi - legend.lo);
    legend.points.push_back({v, kViridis[k][0], kViridis[k][1], kViridis[k][2]});
  }
  return legend;
}

}  // namespace tg::paraview
