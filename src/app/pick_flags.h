#pragma once
// render's --pick I J (repeatable): pixels whose content is printed as JSON
// Lines on stdout after the image is written (app/pick_json.h).
#include <vector>

#include "app/scale/option_table.h"

#include "app/pick.h"

namespace tg::app {

struct PickFlags {
  std::vector<PixelIJ> pixels;  // in the order given

  void addTo(OptionTable& ap);
  // UsageError for a pixel outside the width x height image: checked before
  // anything is loaded or rendered.
  void validate(int width, int height) const;
};

}  // namespace tg::app
