#pragma once
// Small line plots for benchmark reports, drawn with OpenImageIO's
// ImageBufAlgo (lines, boxes, text) and written as PNG.
#include <string>
#include <vector>

#include "io/core/plot_panels.h"

namespace tg::app {

using io::PlotPanel;
using io::PlotSeries;

// Panels side by side, each w x h pixels, written to `path` through a
// temporary file. Throws std::runtime_error "writePlot: path: problem".
// Returns false when no font was found, so the plot has no text.
bool writePlot(const std::vector<PlotPanel>& panels, const std::string& path, int w = 640, int h = 480);

}  // namespace tg::app
