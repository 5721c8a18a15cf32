#pragma once
// A number as a message shows it: "%g", six significant digits, no trailing
// zeros ("-2", "0.37", "1e+300"). Shared by io's warnings and the CLI's.
#include <cstdio>
#include <string>

namespace tg::util {

inline std::string numberText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace tg::util
