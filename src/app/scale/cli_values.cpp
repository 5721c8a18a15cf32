#include "app/scale/cli_values.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <filesystem>

#include "io/field/atomic_file.h"
#include "util/number_text.h"
#include "util/strict_number.h"

namespace tg::app {

// Command-line values are read as file text is (util/strict_number.h): whole
// decimal numbers, a leading '+' allowed.
double parseDouble(std::string_view flag, std::string_view text) {
  // "--ortho --fov 30": the parser gave the next flag as the value.
  if (text.size() > 2 && text.starts_with("--") && !std::isdigit(static_cast<unsigned char>(text[2])))
    throw UsageError(std::string(flag) + ": a number is missing (found the option " + std::string(text) + ")");
  const std::optional<double> v = util::parseFinite(text);
  if (!v) throw UsageError(std::string(flag) + ": \"" + std::string(text) + "\" is not a finite number");
  return *v;
}

double parseDoubleIn(std::string_view flag, std::string_view text, double lo, double hi) {
  const double v = parseDouble(flag, text);
  if (!(v >= lo && v <= hi)) {
    std::ostringstream range;
    range << flag << " must be within " << lo << ".." << hi;
    throw UsageError(range.str());
  }
  return v;
}

long long parseInt(std::string_view flag, std::string_view text) {
  const std::optional<long long> v = util::parseInteger(text);
  if (!v) throw UsageError(std::string(flag) + ": \"" + std::string(text) + "\" is not an integer");
  return *v;
}

long long parseInt(std::string_view flag, std::string_view text, long long lo, long long hi) {
  const std::optional<long long> v = util::parseInteger(text);
  if (!v || *v < lo || *v > hi)
    throw UsageError(std::string(flag) + ": \"" + std::string(text) + "\" is not an integer within " +
                     std::to_string(lo) + ".." + std::to_string(hi));
  return *v;
}

void checkOutputPath(std::string_view flag, const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (const std::string why = io::unwritableTarget(path); !why.empty())
    throw UsageError(std::string(flag) + ": \"" + path + "\" " + why);
  const fs::path dir = fs::path(path).parent_path();
  if (!dir.empty() && !fs::is_directory(dir, ec))
    throw UsageError(std::string(flag) + ": \"" + path + "\": no directory \"" + dir.string() + "\"");
}

glm::dvec3 parseVec3(std::string_view flag, std::span<const char* const> a) {
  if (a.size() != 3) throw UsageError(std::string(flag) + " needs 3 numbers");
  return {parseDouble(flag, a[0]), parseDouble(flag, a[1]), parseDouble(flag, a[2])};
}

std::string formatNumber(double v) { return util::numberText(v); }

namespace {

// The length of the well-formed UTF-8 sequence (of a character from U+0080)
// that `s` begins with; 0 if none: stray bytes from a binary header would
// reach the terminal as they are.
std::size_t utf8Length(std::string_view s) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(0);
  const std::size_t n = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
  if (n == 0 || s.size() < n) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((b(k) & 0xc0) != 0x80) return 0;
  // Overlong forms, UTF-16 surrogates and beyond U+10FFFF.
  if ((c == 0xe0 && b(1) < 0xa0) || (c == 0xed && b(1) > 0x9f) || (c == 0xf0 && b(1) < 0x90) ||
      (c == 0xf4 && b(1) > 0x8f))
    return 0;
  return n;
}

}  // namespace

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7f) {
      out += ch;
      continue;
    }
    if (const std::size_t n = utf8Length(text.substr(i)); n) {  // a name in UTF-8 stays as it is
      out += text.substr(i, n);
      i += n - 1;
      continue;
    }
    char esc[8];
    if (c == '\n') std::snprintf(esc, sizeof esc, "\\n");
    else if (c == '\t') std::snprintf(esc, sizeof esc, "\\t");
    else if (c == '\r') std::snprintf(esc, sizeof esc, "\\r");
    else std::snprintf(esc, sizeof esc, "\\x%02x", unsigned(c));
    out += esc;
  }
  return out;
}

}  // namespace tg::app
