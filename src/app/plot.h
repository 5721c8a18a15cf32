#pragma once
// Small line plots for benchmark reports, drawn with OpenImageIO's
// ImageBufAlgo (lines, boxes, text) and written as PNG.
#include <array>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace tg::app {

struct PlotSeries {
  std::string label;
  std::array<float, 3> rgb{};
  std::vector<glm::dvec2> points;  // drawn in this order, joined by lines
};

struct PlotPanel {
  std::string title, xLabel, yLabel;
  // Log-scaled y; values <= 0 are drawn at the panel's floor, which the axis
  // labels as "<= floor".
  bool logY = true;
  std::vector<PlotSeries> series;
};

// Panels side by side, each w x h pixels, written to `path` through a
// temporary file. Throws std::runtime_error "writePlot: path: problem".
// Returns false when no font was found, so the plot has no text.
bool writePlot(const std::vector<PlotPanel>& panels, const std::string& path, int w = 640, int h = 480);

}  // namespace tg::app
