#pragma once
// The benchmarks behind `tensorglyph bench NAME`, each parsing its own options.

namespace tg::app {

int benchAccuracy(int argc, const char** argv);
int benchScale(int argc, const char** argv);

}  // namespace tg::app
