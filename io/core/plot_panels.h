#pragma once
// What a benchmark plot shows, as the OpenImageIO module (io/core/oiio_module.h)
// draws it; app/plot.h writes plots of these.
#include <array>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace tg::io {

struct PlotSeries {
  std::string label;
  std::array<float, 3> rgb{};
  std::vector<glm::dvec2> points;  // drawn in this order, joined by lines
  // Optional, one per point: its label, drawn beside it; its spread along x
  // (lo, hi), drawn as a bar through it.
  std::vector<std::string> pointLabels;
  std::vector<glm::dvec2> xSpread;
  int marked = -1;  // a point drawn boxed, with markLabel beside it (a default setting)
  std::string markLabel;
};

struct PlotPanel {
  std::string title, xLabel, yLabel;
  // Log-scaled y; values <= 0 are drawn at the panel's floor, which the axis
  // labels as "<= floor".
  bool logY = true;
  std::vector<PlotSeries> series;
};

// Draws `panels` into `rgb` (io/modules/oiio/plot_draw.cpp, inside the module).
bool drawPlot(const std::vector<PlotPanel>& panels, int w, int h, std::vector<float>& rgb);

}  // namespace tg::io
