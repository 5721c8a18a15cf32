#include "io/modules/teem/nrrd_numbers.h"

#include <teem/air.h>
#include <teem/nrrd.h>

#include <cmath>
#include <string_view>

#include "io/field/tensor_field.h"
#include "util/strict_number.h"

namespace tg::io {
namespace {

enum class Grammar { None, Integers, Numbers, Vectors };

Grammar grammarOf(int field) {
  switch (field) {
    case nrrdField_dimension:
    case nrrdField_space_dimension:
    case nrrdField_block_size:
    case nrrdField_sizes:
    case nrrdField_line_skip:
    case nrrdField_byte_skip: return Grammar::Integers;
    case nrrdField_spacings:
    case nrrdField_thicknesses:
    case nrrdField_axis_mins:
    case nrrdField_axis_maxs:
    case nrrdField_min:
    case nrrdField_max:
    case nrrdField_old_min:
    case nrrdField_old_max: return Grammar::Numbers;
    case nrrdField_space_origin:
    case nrrdField_space_directions:
    case nrrdField_measurement_frame: return Grammar::Vectors;
    default: return Grammar::None;
  }
}

bool blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// What is wrong with `value` under `g`, or "" when nothing is.
std::string problem(Grammar g, std::string_view value) {
  auto quoted = [](std::string_view s) {
    std::string q(1, '"');
    return q.append(s).append(1, '"');
  };
  for (std::size_t k = 0; k < value.size();) {
    while (k < value.size() && blank(value[k])) ++k;
    if (k == value.size()) break;
    if (g == Grammar::Vectors && value[k] == '(') {
      // Teem: "(" components separated by "," ")", each read by sscanf.
      const std::size_t close = value.find(')', k);
      if (close == std::string_view::npos) return quoted(value.substr(k)) + " has no closing \")\"";
      const std::string_view vec = value.substr(k, close + 1 - k);
      std::string_view inner = vec.substr(1, vec.size() - 2);
      for (std::size_t from = 0;;) {
        const std::size_t comma = inner.find(',', from);
        const std::string_view c = trimmed(inner.substr(from, comma == std::string_view::npos ? comma : comma - from));
        if (!util::parseNumber(c)) return quoted(vec) + " holds " + quoted(c) + ", which is not a number";
        if (comma == std::string_view::npos) break;
        from = comma + 1;
      }
      k = close + 1;
      if (k < value.size() && !blank(value[k])) return quoted(vec) + " is followed by " + quoted(value.substr(k));
      continue;
    }
    std::size_t e = k;
    while (e < value.size() && !blank(value[e])) ++e;
    const std::string_view word = value.substr(k, e - k);
    k = e;
    if (g == Grammar::Vectors) {
      if (word != "none") return quoted(word) + " is neither a vector \"(x,y,z)\" nor none";
    } else if (g == Grammar::Integers) {
      if (!util::parseInteger(word)) return quoted(word) + " is not an integer";
    } else if (!util::parseNumber(word)) {
      return quoted(word) + " is not a number";
    }
  }
  return "";
}

}  // namespace

void checkNrrdHeaderNumbers(const char* who, const std::string& path, FILE* in) {
  std::string line;
  auto judge = [&](std::size_t lineNo) {
    // Teem's field test: the first ": ", unless a ":=" (key/value) comes first.
    const std::size_t colon = line.find(": "), equal = line.find(":=");
    if (line.empty() || line[0] == '#' || colon == std::string::npos || (equal != std::string::npos && equal < colon))
      return;
    const int field = airEnumVal(nrrdField, line.substr(0, colon).c_str());
    const Grammar g = grammarOf(field);
    if (g == Grammar::None) return;
    if (const std::string p = problem(g, std::string_view(line).substr(colon + 2)); !p.empty())
      throw InputError(std::string(who) + ": " + path + ": header line " + std::to_string(lineNo) + " (" +
                       airEnumStr(nrrdField, field) + "): " + p);
  };
  // Lines end as Teem's airOneLine ends them ("\n", "\r\n" or "\r"); the
  // header ends at its first empty line.
  std::size_t lineNo = 1;
  for (int c; (c = std::fgetc(in)) != EOF;) {
    if (c == '\r') {
      const int next = std::fgetc(in);
      if (next != '\n' && next != EOF) std::ungetc(next, in);
      c = '\n';
    }
    if (c != '\n') {
      line.push_back(char(c));
      continue;
    }
    if (line.empty()) break;
    if (lineNo > 1) judge(lineNo);
    line.clear();
    ++lineNo;
  }
  if (lineNo > 1 && !line.empty()) judge(lineNo);
  std::clearerr(in);
  std::rewind(in);
}

}  // namespace tg::io
