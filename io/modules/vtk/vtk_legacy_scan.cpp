#include "io/modules/vtk/vtk_legacy_scan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "io/field/tensor_field.h"
#include "util/strict_number.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readVtk: " + path + ": " + what);
}

// A legacy header states counts that VTK allocates before reading. Every
// value takes at least one byte of the file, so a count beyond the file size
// is corrupt; rejecting it here keeps a 20-byte file from allocating terabytes.
std::uint64_t typeSize(const std::string& t) {
  if (t == "double" || t == "long" || t == "unsigned_long" || t == "vtkIdType") return 8;
  if (t == "float" || t == "int" || t == "unsigned_int") return 4;
  if (t == "short" || t == "unsigned_short") return 2;
  return 1;
}

constexpr std::size_t kVtkNameMax = 255;

// VTK's ASCII reader never returns from a run of 256 or more spaces (one
// line) between numbers and the next keyword or the end of the file: the
// file read until the time limit stopped it. Fed line by line.
class SpaceRunAfterNumbers {
 public:
  // Throws (through fail) when `line` is a keyword line that such a run precedes.
  void line(const std::string& path, const std::string& text, int lineNo) {
    const std::size_t first = text.find_first_not_of(' ');
    if (first == std::string::npos) {  // blank: part of the gap
      if (numbers_) run_ = std::max(run_, text.size());
      return;
    }
    std::string word = text.substr(first, text.find_first_of(" \t\r", first) - first);
    std::transform(word.begin(), word.end(), word.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
    const char c = word.empty() ? '\t' : word[0];
    const bool number = std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.' ||
                        word.rfind("nan", 0) == 0 || word.rfind("inf", 0) == 0;
    if (!number && std::isalpha(static_cast<unsigned char>(c))) {
      if (numbers_ && std::max(run_, first) >= kRun) failAt(path, lineNo);
      numbers_ = false;
    } else if (number) {
      numbers_ = true;
      const std::size_t last = text.find_last_not_of(" \r");
      run_ = text.size() - 1 - last;
      runLine_ = lineNo;
      return;
    }
    run_ = 0;
  }
  void end(const std::string& path) const {
    if (numbers_ && run_ >= kRun) failAt(path, -1);
  }

 private:
  static constexpr std::size_t kRun = 256;
  [[noreturn]] void failAt(const std::string& path, int lineNo) const {
    fail(path, "a run of 256 or more spaces after the numbers of line " + std::to_string(runLine_ + 1) + ", before " +
                   (lineNo < 0 ? std::string("the end") : "line " + std::to_string(lineNo + 1)) +
                   ": VTK's legacy reader never reads past it; remove the spaces");
  }
  bool numbers_ = false;
  std::size_t run_ = 0;
  int runLine_ = 0;
};

// VTK's ASCII reader streams numbers (operator>>), which stop at the first
// character that cannot continue one: "1,5" read as 1 and ",5" then as the
// next keyword, and the file was refused as having no point tensors, or
// read on with a wrong value where the rest parsed. Every word of a data
// line (one beginning with a number), and the numbers after the keywords
// that take them, must be whole numbers (util/strict_number.h).
void checkAsciiNumbers(const std::string& path, const std::string& line, int lineNo) {
  std::istringstream ls(line);
  std::vector<std::string> w;
  for (std::string word; ls >> word;) w.push_back(word);
  if (w.empty()) return;
  auto refuse = [&](const std::string& word) {
    fail(path, "line " + std::to_string(lineNo + 1) + ": \"" + word + "\" is not a number");
  };
  const char c = w[0][0];
  if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.') {
    // A FIELD array's line: NAME COMPONENTS TUPLES TYPE, whose name may begin with a digit.
    if (w.size() == 4 && util::parseInteger(w[1]) && util::parseInteger(w[2]) &&
        std::isalpha(static_cast<unsigned char>(w[3][0])))
      return;
    // Beyond double's range ("1e999") is left to the checks that say "not finite".
    for (const std::string& word : w)
      if (!util::parseNumber(word) && !util::outOfRange(word)) refuse(word);
    return;
  }
  std::string key = w[0];
  std::transform(key.begin(), key.end(), key.begin(), [](unsigned char ch) { return char(std::toupper(ch)); });
  // Where each keyword's numbers are: from word `first`, `count` of them.
  std::size_t first = 1, count = 0;
  if (key == "DIMENSIONS" || key == "SPACING" || key == "ORIGIN" || key == "ASPECT_RATIO") count = 3;
  else if (key == "POINTS" || key == "POINT_DATA" || key == "CELL_DATA" || key == "CELL_TYPES" ||
           key == "X_COORDINATES" || key == "Y_COORDINATES" || key == "Z_COORDINATES")
    count = 1;
  else if (key == "CELLS" || key == "POLYGONS" || key == "LINES" || key == "VERTICES" || key == "TRIANGLE_STRIPS")
    count = 2;
  else if (key == "FIELD" || key == "COLOR_SCALARS" || key == "TEXTURE_COORDINATES") first = 2, count = 1;
  else if (key == "SCALARS") first = 3, count = 1;
  else if (key == "LOOKUP_TABLE" && w.size() > 2) first = 2, count = 1;
  for (std::size_t k = first; k < std::min(w.size(), first + count); ++k)
    if (!util::parseNumber(w[k]) && !util::outOfRange(w[k])) refuse(w[k]);
}

// An ASCII legacy (< 5.0) cell list, "count id..." per cell, walked as it is
// read: VTK imports it trusting each count, so "LINES 1 4 / 9 0 1 2" read
// five ids past its buffer and drew them as points (vtkCellArray::
// ImportLegacyFormat). The counts must fill the header's size exactly.
class LegacyCellList {
 public:
  void begin(const std::string& key, long double cells, long double size) {
    key_ = key;
    cells_ = std::uint64_t(cells);
    size_ = valuesLeft_ = std::uint64_t(size);
    cellsLeft_ = cells_;
    idsLeft_ = 0;
  }
  bool active() const { return valuesLeft_ > 0; }
  // The line's values; false when the line is no part of the list.
  bool line(const std::string& path, const std::string& text) {
    if (!active()) return false;
    std::istringstream ls(text);
    for (std::string word; valuesLeft_ > 0 && ls >> word; --valuesLeft_) {
      const std::optional<long long> v = util::parseInteger(word);
      if (!v) fail(path, "\"" + key_ + "\": \"" + word + "\" is not a point count or id");
      if (idsLeft_ > 0) {
        --idsLeft_;
        continue;
      }
      if (cellsLeft_ == 0 || *v < 0 || std::uint64_t(*v) >= valuesLeft_)
        fail(path, "\"" + key_ + "\" " + std::to_string(cells_) + " " + std::to_string(size_) + ": cell " +
                       std::to_string(cells_ - cellsLeft_) + "'s point count " + word +
                       (cellsLeft_ == 0 ? " lies beyond its cells" : " runs past the list's size"));
      --cellsLeft_;
      idsLeft_ = std::uint64_t(*v);
    }
    if (valuesLeft_ == 0 && cellsLeft_ > 0)
      fail(path, "\"" + key_ + "\" " + std::to_string(cells_) + " " + std::to_string(size_) + ": its size holds " +
                     std::to_string(cells_ - cellsLeft_) + " of the cells");
    return true;
  }

 private:
  std::string key_;
  std::uint64_t cells_ = 0, size_ = 0, cellsLeft_ = 0, valuesLeft_ = 0, idsLeft_ = 0;
};

}  // namespace

// Every value takes at least one byte (ASCII) or its binary size, so a
// header count beyond the file size is corrupt and a binary file shorter than
// its arrays is truncated (VTK's binary reader does not notice). Rejecting
// both here keeps a 20-byte file from allocating terabytes.
std::uint64_t checkLegacyCounts(const std::string& path, std::uint64_t fileSize) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::uint64_t points = 0;
  bool binary = false, newCellFormat = false, trailer = false;
  std::uint64_t tuples = 0;
  long double dataBytes = 0;  // lower bound for binary files
  auto impossible = [&](const std::string& key, long double values) {
    if (values > (long double)fileSize) fail(path, key + " count exceeds the file size");
  };
  SpaceRunAfterNumbers spaces;
  LegacyCellList cellList;
  for (int lineNo = 0; std::getline(in, line); ++lineNo) {
    if (lineNo == 0) newCellFormat = line.find("Version 5") != std::string::npos;
    if (lineNo == 2) binary = line.rfind("BINARY", 0) == 0;
    if (!binary && lineNo > 2) spaces.line(path, line, lineNo);
    // 3D-TSV's stress trailer is read, strictly, by io/core/tsv_trailer.cpp.
    trailer |= line.rfind("Cartesian Stress:", 0) == 0;
    if (!binary && lineNo > 2 && !trailer) checkAsciiNumbers(path, line, lineNo);
    if (!binary && cellList.line(path, line)) continue;
    // A binary file's arrays are read as lines too, and their bytes can spell
    // a keyword and numbers; header lines are printable text.
    if (binary && lineNo > 2 && !std::all_of(line.begin(), line.end(), [](unsigned char ch) {
          return (ch >= 0x20 && ch < 0x7f) || ch == '\t' || ch == '\r';
        }))
      continue;
    std::istringstream ls(line);
    std::string key, type;
    ls >> key;
    if (key.empty() || !std::isalpha(static_cast<unsigned char>(key[0]))) continue;
    // VTK matches keywords by prefix ("CELLS13" is read as CELLS), so a
    // glued keyword would slip past the counts checked below.
    std::string lower = key;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
    for (const char* k : {"points", "cells", "cell_types", "polygons", "lines", "vertices", "triangle_strips",
                          "point_data", "cell_data", "dimensions", "tensors", "scalars", "vectors", "normals", "field"})
      if (lower.rfind(k, 0) == 0 && lower != k && !(std::string(k) == "cells" && lower == "cell_types") &&
          !(std::string(k) == "points" && lower == "point_data") && lower != "tensors6")
        fail(path, "malformed keyword \"" + key + "\"");
    // VTK compares keywords case-insensitively, and so must the counts.
    key = lower;
    std::transform(key.begin(), key.end(), key.begin(), [](unsigned char ch) { return char(std::toupper(ch)); });
    // VTK reads a keyword or an array's name 255 bytes at a time
    // (vtkDataReader::ReadString): a longer name was cut, its tail read as
    // the data type, and the array lost ("no point tensors") or misread.
    std::string name = lower;
    for (const char* k : {"scalars", "vectors", "normals", "tensors", "tensors6", "texture_coordinates",
                          "color_scalars", "field"})
      if (lower == k) std::istringstream(line) >> name >> name;
    if (name.size() > kVtkNameMax)
      fail(path, "a name of " + std::to_string(name.size()) + " bytes (" + name.substr(0, 16) +
                     "...); VTK's legacy reader takes at most " + std::to_string(kVtkNameMax));
    long double a = -1, b = -1, c = -1;
    if (key == "POINTS" && (ls >> a >> type)) {
      impossible(key, 3 * a);
      dataBytes += 3 * a * typeSize(type);
      points = std::max(points, std::uint64_t(std::max<long double>(a, 0)));
    } else if ((key == "POINT_DATA" || key == "CELL_DATA") && (ls >> a)) {
      impossible(key, a);
      tuples = std::uint64_t(std::max<long double>(a, 0));
      if (key == "POINT_DATA") points = std::max(points, tuples);
    } else if ((key == "CELLS" || key == "VERTICES" || key == "LINES" || key == "POLYGONS" ||
                key == "TRIANGLE_STRIPS") && (ls >> a >> b)) {
      if (a < 0 || b < 0) fail(path, "negative count in \"" + key + "\"");
      impossible(key, a);
      impossible(key, b);
      // Legacy (< 5.0) lists "count id..." per cell, at least two values;
      // 5.x gives offsets (cells + 1) and connectivity sizes. VTK reads a
      // size too small for its count into a null buffer (found by fuzz_vtk).
      if (newCellFormat ? (a > 1 && b < a - 1) : b < 2 * a)
        fail(path, "\"" + key + "\" size " + std::to_string((long long)b) + " is too small for " +
                       std::to_string((long long)a) + " cells");
      if (!binary && !newCellFormat) cellList.begin(key, a, b);
    } else if (key == "SPACING" || key == "ORIGIN" || key == "ASPECT_RATIO") {
      // VTK's stream stops at "nan" or "inf" and reads no arrays at all, which
      // was then reported as a file without tensors.
      for (std::string word; ls >> word;) {
        char* end = nullptr;
        const double v = std::strtod(word.c_str(), &end);
        if (end == word.c_str() + word.size() && !std::isfinite(v)) fail(path, key + ": " + word + " is not finite");
      }
    } else if (key == "CELL_TYPES" && (ls >> a)) {
      impossible(key, a);
    } else if (key == "DIMENSIONS" && (ls >> a >> b >> c)) {
      if (a < 1 || b < 1 || c < 1) fail(path, "DIMENSIONS must be positive");
      impossible(key, a * b * c);
      points = std::max(points, std::uint64_t(a * b * c));
    } else if ((key == "TENSORS" || key == "TENSORS6") && (ls >> type >> type)) {
      dataBytes += (key == "TENSORS" ? 9.0L : 6.0L) * tuples * typeSize(type);
    } else if ((key == "VECTORS" || key == "NORMALS") && (ls >> type >> type)) {
      dataBytes += 3.0L * tuples * typeSize(type);
    } else if (key == "COLOR_SCALARS" && (ls >> type >> a)) {
      impossible(key, a * tuples);
      dataBytes += a * tuples;  // unsigned char when binary
    } else if (key == "LOOKUP_TABLE" && (ls >> type >> a)) {
      impossible(key, 4 * a);
      dataBytes += 4 * a;
    } else if (key == "TEXTURE_COORDINATES" && (ls >> type >> a >> type)) {
      impossible(key, a * tuples);
      dataBytes += a * tuples * typeSize(type);
    } else if (key == "SCALARS" && (ls >> type >> type)) {
      long double n = 1;
      ls >> n;
      dataBytes += n * tuples * typeSize(type);
    } else if (ls >> a >> b >> type && a >= 0 && b >= 0 && typeSize(type) > 1) {
      // A FIELD array: NAME COMPONENTS TUPLES TYPE
      impossible("field array", a * b);
      dataBytes += a * b * typeSize(type);
    }
    if (a < -1 || b < -1 || c < -1) fail(path, "negative count in \"" + key + "\"");
  }
  if (!binary) spaces.end(path);
  if (binary && dataBytes > (long double)fileSize)
    fail(path, "file is truncated: its header describes " + std::to_string(std::uint64_t(dataBytes)) +
                   " bytes of binary data, the file has " + std::to_string(fileSize));
  return points;
}

}  // namespace tg::io
