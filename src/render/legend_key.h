#pragma once
// What scene context adds to the legend: the key of a slice plane's
// underlay (render/slice_plane.h), the value range its colormap spans.
#include <string>

#include "view/underlay.h"

namespace tg::render {

struct UnderlayKey {
  std::string name;  // what the planes show: the file, or the field's scalar (fa, md, ...)
  Colormap colormap = Colormap::Gray;
  double lo = 0, hi = 1;  // the window: values at the colormap's ends, clamped beyond
  bool operator==(const UnderlayKey&) const = default;
};

}  // namespace tg::render
