#pragma once
// Numbers read from input text, whole or not at all. C's readers (sscanf,
// atof, strtod, stream >>) take the longest prefix that is a number, so
// "3,5" read as 3, "1.5abc" as 1.5 and "0x10" as 0 or 16, and files drew
// with those values. Every text number the project reads from a file goes
// through here, or through a check that the library's own reading of it
// agrees (io/modules/teem/nrrd_numbers.h, io/modules/vtk/mesh_text_checks.h).
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace tg::util {

// "nan", "inf" or "infinity" (any case, optionally signed): its value.
inline std::optional<double> nonFiniteWord(std::string_view t) {
  bool negative = false;
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) {
    negative = t[0] == '-';
    t.remove_prefix(1);
  }
  std::string w(t);
  for (char& c : w) c = char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  if (w == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (w == "inf" || w == "infinity")
    return negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  return std::nullopt;
}

namespace detail {
enum class Decimal { Ok, OutOfRange, Malformed };
// `text` as [+-] digits [. digits] [(e|E) [+-] digits], whole, into `v`.
inline Decimal decimal(std::string_view text, double& v) {
  // from_chars takes no '+', and reads "nan(...)" and "-inf" itself: only
  // digits or a point may follow the sign here.
  std::string_view digits = text;
  if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);
  const std::size_t lead = !digits.empty() && digits[0] == '-' && text[0] != '+' ? 1 : 0;
  if (digits.size() <= lead || !((digits[lead] >= '0' && digits[lead] <= '9') || digits[lead] == '.'))
    return Decimal::Malformed;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v, std::chars_format::general);
  if (end != digits.data() + digits.size()) return Decimal::Malformed;
  if (ec == std::errc::result_out_of_range) {
    const std::string copy(digits);
    v = std::strtod(copy.c_str(), nullptr);
    return std::isfinite(v) ? Decimal::Ok : Decimal::OutOfRange;  // underflow gives strtod's value
  }
  return ec == std::errc() ? Decimal::Ok : Decimal::Malformed;
}
}  // namespace detail

// All of `text` as one decimal number: [+-] digits [. digits] [(e|E) [+-]
// digits], with a digit on at least one side of the point, or a non-finite
// word (nonFiniteWord). No spaces, commas, hex or trailing characters. A
// value beyond double's range is refused (outOfRange tells it apart); one
// below it gives what strtod gives (a subnormal or a signed zero).
inline std::optional<double> parseNumber(std::string_view text) {
  if (const auto w = nonFiniteWord(text)) return w;
  double v = 0;
  if (detail::decimal(text, v) != detail::Decimal::Ok) return std::nullopt;
  return v;
}

// Whether `text` is a well-formed decimal number beyond double's range ("1e999").
inline bool outOfRange(std::string_view text) {
  double v = 0;
  return detail::decimal(text, v) == detail::Decimal::OutOfRange;
}

// parseNumber, finite values only.
inline std::optional<double> parseFinite(std::string_view text) {
  const auto v = parseNumber(text);
  return v && std::isfinite(*v) ? v : std::nullopt;
}

// All of `text` as a decimal integer: [+-] digits, within long long.
inline std::optional<long long> parseInteger(std::string_view text) {
  const bool plus = !text.empty() && text[0] == '+';
  if (plus) text.remove_prefix(1);
  if (text.empty() || (plus && text[0] == '-')) return std::nullopt;
  long long v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

}  // namespace tg::util
