#include "io/modules/vtk/vtk_nonfinite.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>

#include "io/field/tensor_field.h"

namespace tg::io {
namespace {

// Tiny normal values with many significant digits: no measurement holds them
// by chance, and each is checked against the file's own numbers anyway.
constexpr const char* kCandidates[] = {"1.17549435e-37", "1.23456789e-36", "2.71828183e-35", "3.14159265e-34",
                                       "1.61803399e-33", "1.41421356e-32", "1.73205081e-31", "2.23606798e-30"};

bool isNonFiniteWord(const std::string& t) {
  std::size_t b = t[0] == '+' || t[0] == '-' ? 1 : 0;
  std::string w;
  for (std::size_t k = b; k < t.size(); ++k) w += char(std::tolower(static_cast<unsigned char>(t[k])));
  return w == "nan" || w == "inf" || w == "infinity";
}

// The token as a number, if all of it is one. float(d) of a value parsed as
// double can differ from strtof of the text in the last bit; the sentinels
// are far from any such rounding boundary.
bool numberOf(const std::string& t, double& d) {
  char* end = nullptr;
  d = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

}  // namespace

NonFiniteText NonFiniteText::replace(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  // Pass 1: the lines that hold only numbers and non-finite words, the
  // words' places, and every number the file holds (for the sentinels).
  struct Word {
    std::size_t at, len;
    bool nan, negative;
  };
  std::vector<Word> words;
  // Which candidates occur among the file's own numbers, as double or float.
  constexpr std::size_t kCount = std::size(kCandidates);
  double candD[kCount];
  float candF[kCount];
  bool taken[kCount] = {};
  for (std::size_t c = 0; c < kCount; ++c) {
    candD[c] = std::strtod(kCandidates[c], nullptr);
    candF[c] = std::strtof(kCandidates[c], nullptr);
  }
  for (std::size_t lineStart = 0; lineStart < text.size();) {
    std::size_t lineEnd = text.find('\n', lineStart);
    if (lineEnd == std::string::npos) lineEnd = text.size();
    std::vector<Word> lineWords;
    bool numeric = true;
    for (std::size_t k = lineStart; k < lineEnd && numeric;) {
      while (k < lineEnd && std::isspace(static_cast<unsigned char>(text[k]))) ++k;
      const std::size_t s = k;
      while (k < lineEnd && !std::isspace(static_cast<unsigned char>(text[k]))) ++k;
      if (k == s) break;
      const std::string t = text.substr(s, k - s);
      if (isNonFiniteWord(t)) {
        const char c = char(std::tolower(static_cast<unsigned char>(t[t[0] == '+' || t[0] == '-' ? 1 : 0])));
        lineWords.push_back({s, k - s, c == 'n', t[0] == '-'});
      } else if (double d; numberOf(t, d)) {
        const double a = std::abs(d);
        const float af = std::abs(float(d));
        // Only tiny values can match: skip the comparisons for the rest.
        if (a < 1e-29)
          for (std::size_t c = 0; c < kCount; ++c) taken[c] = taken[c] || a == candD[c] || af == candF[c];
      } else {
        numeric = false;  // a keyword line: names there are not values
      }
    }
    if (numeric) words.insert(words.end(), lineWords.begin(), lineWords.end());
    lineStart = lineEnd + 1;
  }
  NonFiniteText r;
  if (words.empty()) return r;
  std::vector<const char*> free;
  for (std::size_t c = 0; c < kCount; ++c)
    if (!taken[c]) free.push_back(kCandidates[c]);
  if (free.size() < 2) throw InputError("readVtk: " + path + ": cannot stand in for its NaN/Inf values");
  const std::string nanText = free[0], infText = free[1];
  r.nanD_ = std::strtod(free[0], nullptr), r.nanF_ = double(std::strtof(free[0], nullptr));
  r.infD_ = std::strtod(free[1], nullptr), r.infF_ = double(std::strtof(free[1], nullptr));
  // Pass 2: the copy, each word replaced by its sentinel (with the sign of an infinity).
  r.text_.reserve(text.size() + words.size() * 16);
  std::size_t from = 0;
  for (const Word& w : words) {
    r.text_.append(text, from, w.at - from);
    if (!w.nan && w.negative) r.text_ += '-';
    r.text_ += w.nan ? nanText : infText;
    from = w.at + w.len;
  }
  r.text_.append(text, from, std::string::npos);
  r.replaced_ = words.size();
  return r;
}

double NonFiniteText::restore(double v) const {
  if (replaced_ == 0) return v;
  const double a = std::abs(v);
  if (a == nanD_ || a == nanF_) return std::numeric_limits<double>::quiet_NaN();
  if (a == infD_ || a == infF_) return std::copysign(std::numeric_limits<double>::infinity(), v);
  return v;
}

}  // namespace tg::io
