#include "app/pick_flags.h"

#include <string>

#include "app/scale/cli_values.h"
#include "app/scale/frame_size.h"

namespace tg::app {

void PickFlags::addTo(OptionTable& ap) {
  using Args = OptionArgs;
  ap.arg("--pick I J").commandLineOnly()
      .help("print what pixel (I, J) shows as one line of JSON on stdout: column I, row J from the top "
            "(docs/guide.md, \"Picking\")")
      .repeats().range({0, kMaxFrameSide - 1, true}).action([this](Args a) {
        pixels.push_back({int(parseInt(a[0], a[1])), int(parseInt(a[0], a[2]))});
      });
}

void PickFlags::validate(int width, int height) const {
  for (const PixelIJ& p : pixels)
    if (p.i >= width || p.j >= height)
      throw UsageError("--pick: pixel (" + std::to_string(p.i) + ", " + std::to_string(p.j) + ") is outside the " +
                       std::to_string(width) + " x " + std::to_string(height) + " image");
}

}  // namespace tg::app
