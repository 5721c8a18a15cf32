#pragma once
// Progress of long work, told to whoever asked for it: the command line draws
// it on a terminal (app/progress.h); a Python caller will pass a callback of
// its own. Work reports once per block of items (a chunk of tensors, a file
// position, a frame), never per item, so an empty sink costs one test per
// block.
#include <functional>
#include <string_view>

namespace tg::util {

// `done` of `total` units of `unit` ("bytes", "tensors", "frames") in the
// stage named `stage` ("loading", "eigen", "rendering"); total 0: not known.
// Called from the thread that does the work; a new stage restarts the count.
// An empty stage says the work is about to print a message of its own: a
// progress line on the screen is cleared first, and drawn again on the next
// report.
using ProgressSink =
    std::function<void(std::string_view stage, double done, double total, std::string_view unit)>;

// The render stage's unit: a frame's passes (render::PassProgress), which
// differ in cost (the glyphs' is most of a frame), so that no rate or time
// left is made of them; the time so far is shown instead.
inline constexpr std::string_view kPassesUnit = "passes";

}  // namespace tg::util
