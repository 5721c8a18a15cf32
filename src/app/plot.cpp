#include "app/plot.h"

#include <algorithm>
#include <stdexcept>

#include "io/core/oiio_module.h"
#include "io/core/png_writer.h"

namespace tg::app {
namespace {

// Room a panel needs around its plot area (src/app/plot_draw.cpp).
constexpr int kMinWidth = 78 + 150 + 10, kMinHeight = 36 + 56 + 10;

}  // namespace

bool writePlot(const std::vector<PlotPanel>& panels, const std::string& path, int w, int h) {
  if (panels.empty() || w <= kMinWidth || h <= kMinHeight)
    throw std::runtime_error("writePlot: " + path + ": no panels, or panels too small");
  std::vector<float> rgb;
  const bool labelled = io::oiioModule("writePlot", path).drawPlot(panels, w, h, rgb);
  std::vector<unsigned char> px(rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i)
    px[i] = static_cast<unsigned char>(std::clamp(rgb[i], 0.0f, 1.0f) * 255.0f + 0.5f);
  io::writePng(path, w * int(panels.size()), h, 3, px.data());
  return labelled;
}

}  // namespace tg::app
