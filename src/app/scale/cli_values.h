#pragma once
// Strict parsing of command-line values, shared by the subcommands and the
// EGL-only benchmark executable (so it depends on nothing but the C++ library).
#include <chrono>
#include <ctime>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace tg::app {

// A command-line error: main prints "tensorglyph: <what>" and exits 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Thrown once a command has printed its --help: main exits with status 0.
struct HelpShown {};

// Whole-string numbers only ("1.5x" and "" are errors), finite.
double parseDouble(std::string_view flag, std::string_view text);
// parseDouble within [lo, hi]: "FLAG must be within LO..HI" otherwise.
double parseDoubleIn(std::string_view flag, std::string_view text, double lo, double hi);
long long parseInt(std::string_view flag, std::string_view text);
// An integer within lo..hi, checked before any narrowing: "4294967297" for an
// int option is an error naming the flag and the range, never a wrapped 1.
long long parseInt(std::string_view flag, std::string_view text, long long lo, long long hi);
inline int parseIntIn(std::string_view flag, std::string_view text, int lo, int hi) {
  return int(parseInt(flag, text, lo, hi));
}
glm::dvec3 parseVec3(std::string_view flag, std::span<const char* const> args);

// An output path that can be written: not a directory, in a directory that
// exists. Throws UsageError naming the flag.
void checkOutputPath(std::string_view flag, const std::string& path);

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

// Wall time since t, for the commands' timings.
using Clock = std::chrono::steady_clock;
inline double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// CPU time of the whole process (every thread, llvmpipe's rasterisers
// too) in ms: on a shared machine a frame's CPU time varies far less than
// its wall time.
inline double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// A value as the help texts quote defaults ("%g").
std::string formatNumber(double v);
// "W H", as --size takes it. Appended, not `+ " " +`: GCC 12 warns falsely
// (-Wrestrict) on the concatenation.
inline std::string formatSize(int width, int height) {
  std::string s = std::to_string(width);
  s.append(" ").append(std::to_string(height));
  return s;
}
// A list as its LIST option takes it: "1e-02,0.001" -> "0.01,0.001".
template <class T>
std::string formatList(const std::vector<T>& values) {
  std::string s;
  for (const T& v : values) {
    if (!s.empty()) s.push_back(',');
    s.append(formatNumber(double(v)));
  }
  return s;
}

// Text as a one-line message may show it: control characters (a newline in
// a file's name, a terminal's escape sequences) and DEL become \n, \t, \r
// or \xHH, and a backslash stays one. Every message that reaches the
// terminal passes through it (main, and the load warnings), so that a name
// can neither split the line nor drive the terminal.
std::string printable(std::string_view text);

}  // namespace tg::app
