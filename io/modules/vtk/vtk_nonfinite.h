#pragma once
// Legacy ASCII .vtk files with NaN or Inf. VTK's own writer prints them as
// "nan" and "inf", but its reader parses numbers with C++ streams, which
// cannot read those words, and it resets the global locale before opening a
// file, so no number facet of ours can help. The words are therefore
// replaced, in a copy of the text, by decimal sentinels that occur nowhere
// else in the file, and the values VTK returns are mapped back.
#include <cstdint>
#include <string>

namespace tg::io {

class NonFiniteText {
 public:
  // The file's text with every NaN/Inf word on a numbers-only line replaced;
  // empty() when there is none. InputError if the file holds no sentinel-free
  // choice (it would need every candidate value among its own numbers).
  static NonFiniteText replace(const std::string& path);
  bool empty() const { return replaced_ == 0; }
  std::uint64_t replaced() const { return replaced_; }
  const std::string& text() const { return text_; }
  // A value as VTK read it, sentinels turned back into NaN and ±Inf, whether
  // the array was float or double.
  double restore(double v) const;

 private:
  std::string text_;
  std::uint64_t replaced_ = 0;
  double nanF_ = 0, nanD_ = 0, infF_ = 0, infD_ = 0;
};

}  // namespace tg::io
