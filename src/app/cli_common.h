#pragma once
// Shared pieces of the subcommands: strict value parsing and context creation.
#include <chrono>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "gl/context.h"

namespace tg::app {

// A command-line error: main prints "tensorglyph: <what>" and exits 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whole-string numbers only ("1.5x" and "" are errors), finite.
double parseDouble(std::string_view flag, std::string_view text);
long long parseInt(std::string_view flag, std::string_view text);
glm::dvec3 parseVec3(std::string_view flag, std::span<const char* const> args);

// A comma-separated list, each item through `parse` (parseInt, parseDouble).
template <class T, class Parse>
std::vector<T> parseList(std::string_view flag, std::string_view text, Parse parse) {
  std::vector<T> out;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    out.push_back(T(parse(flag, text.substr(start, comma - start))));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

// "osmesa", "egl", "glfw" or "auto" (a GPU through EGL if present, else OSMesa).
// checkBackend throws UsageError for any other name, so commands can reject
// it before loading anything.
void checkBackend(std::string_view backend);
std::unique_ptr<gl::Context> createContext(std::string_view backend, int width, int height);

// Wall time since t, for the commands' timings.
using Clock = std::chrono::steady_clock;
inline double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// Peak resident memory of this process so far, in bytes.
std::size_t peakRssBytes();

}  // namespace tg::app
