#include "io/modules/vtk/vtk_xml_checks.h"

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string_view>
#include <vector>

#include <vtkAlgorithm.h>
#include <vtkInformation.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLReader.h>

#include "io/field/tensor_field.h"
#include "util/strict_number.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readVtk: " + path + ": " + what);
}

vtkXMLDataElement* rootOf(vtkAlgorithm* reader) {
  auto* xr = vtkXMLReader::SafeDownCast(reader);
  return xr && xr->GetXMLParser() ? xr->GetXMLParser()->GetRootElement() : nullptr;
}

int base64Value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// Base64 text from `at` (past the start tag's '>' when `skipTag`) up to the
// next '<': its first `prefix` bytes decoded into `head`, and the number of
// bytes the whole text decodes to.
std::uint64_t base64Bytes(std::ifstream& in, std::int64_t at, bool skipTag, unsigned char* head, std::size_t prefix) {
  in.clear();
  in.seekg(at);
  if (skipTag)
    for (char c; in.get(c) && c != '>';) {}
  std::uint64_t sextets = 0;
  std::uint32_t acc = 0;
  std::size_t got = 0;
  for (char c; in.get(c) && c != '<';) {
    const int v = base64Value(c);
    if (v < 0) continue;
    acc = (acc << 6) | std::uint32_t(v);
    if (++sextets % 4 == 0)
      for (int k = 2; k >= 0; --k)
        if (got < prefix) head[got++] = static_cast<unsigned char>(acc >> (8 * k));
  }
  return sextets * 3 / 4;
}

// How a file's binary blocks are framed: the size prefix's width and order.
struct Framing {
  std::size_t prefix = 4;
  bool bigEndian = false;
  bool compressed = false;
  std::int64_t appendedStart = -1;  // first byte after AppendedData's '_'
  bool appendedBase64 = false;
  std::uint64_t fileSize = 0;
};

std::uint64_t decodePrefix(const unsigned char* head, const Framing& fr) {
  std::uint64_t v = 0;
  for (std::size_t b = 0; b < fr.prefix; ++b) v = (v << 8) | head[fr.bigEndian ? b : fr.prefix - 1 - b];
  return v;
}

std::string arrayName(vtkXMLDataElement* e) {
  const char* name = e->GetAttribute("Name");
  std::string quoted(1, '"');
  return quoted.append(name ? name : "?").append(1, '"');
}

// An appended raw block at `pos`: its size prefix (or, compressed, its block
// table) and the bytes they promise must lie inside the file.
void checkAppendedRaw(std::ifstream& in, std::uint64_t pos, const Framing& fr, vtkXMLDataElement* e,
                      const std::string& path) {
  auto readPrefix = [&](std::uint64_t at) {
    unsigned char head[8] = {};
    in.clear();
    in.seekg(std::streamoff(at));
    in.read(reinterpret_cast<char*>(head), std::streamsize(fr.prefix));
    return decodePrefix(head, fr);
  };
  auto beyond = [&](std::uint64_t need) {
    fail(path, "appended data of array " + arrayName(e) + " is truncated: it needs " + std::to_string(need) +
                   " bytes from byte " + std::to_string(pos) + ", only " +
                   std::to_string(fr.fileSize > pos ? fr.fileSize - pos : 0) + " remain");
  };
  const std::uint64_t room = fr.fileSize > pos ? fr.fileSize - pos : 0;
  if (room < fr.prefix) beyond(fr.prefix);
  const std::uint64_t first = readPrefix(pos);
  if (!fr.compressed) {
    if (first > room - fr.prefix) beyond(fr.prefix + first);
    return;
  }
  // Compressed: blocks, block size, last block size, then each block's size.
  if (first > room / fr.prefix) beyond(first * fr.prefix);
  std::uint64_t need = (3 + first) * fr.prefix;
  if (need > room) beyond(need);
  for (std::uint64_t k = 0; k < first; ++k) need += readPrefix(pos + (3 + k) * fr.prefix);
  if (need > room) beyond(need);
}

// VTK's parser streams an ascii array's values (operator>>), which stop
// where a number cannot continue: "1.5abc" as the last value read as 1.5,
// "3,5" as 3. Every word must be a whole number, an integer in an integer
// array (util/strict_number.h).
void checkAsciiWords(vtkXMLDataElement* e, std::ifstream& in, const std::string& path) {
  const std::string type = e->GetAttribute("type") ? e->GetAttribute("type") : "";
  const bool integral = type.find("Int") != std::string::npos;
  in.clear();
  in.seekg(e->GetXMLByteIndex());
  for (char c; in.get(c) && c != '>';) {}
  std::string word;
  auto judge = [&] {
    if (word.empty()) return;
    if (integral ? !util::parseInteger(word) : !util::parseNumber(word) && !util::outOfRange(word))
      fail(path, "ascii array " + arrayName(e) + " holds \"" + word + "\", which is not " +
                     (integral ? "an integer" : "a number"));
    word.clear();
  };
  for (char c; in.get(c) && c != '<';) {
    if (std::isspace(static_cast<unsigned char>(c))) judge();
    else if (word.size() < 256) word.push_back(c);
    else fail(path, "ascii array " + arrayName(e) + " holds a word longer than 256 characters");
  }
  judge();
}

void checkArrays(vtkXMLDataElement* e, std::ifstream& in, const Framing& fr, const std::string& path) {
  for (int k = 0; k < e->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* child = e->GetNestedElement(k);
    const char* format = child->GetAttribute("format");
    const bool array = std::strcmp(child->GetName(), "DataArray") == 0 && format;
    if (array && std::strcmp(format, "ascii") == 0) checkAsciiWords(child, in, path);
    if (array && std::strcmp(format, "binary") == 0 && !fr.compressed) {
      unsigned char head[8] = {};
      const std::uint64_t have = base64Bytes(in, child->GetXMLByteIndex(), true, head, fr.prefix);
      const std::uint64_t declared = decodePrefix(head, fr);
      if (have < fr.prefix || have - fr.prefix < declared)
        fail(path, "inline data of array " + arrayName(child) + " is truncated: it declares " +
                       std::to_string(declared) + " bytes and holds " +
                       std::to_string(have > fr.prefix ? have - fr.prefix : 0));
    } else if (array && std::strcmp(format, "appended") == 0) {
      long long offset = 0;
      if (!child->GetScalarAttribute("offset", offset) || offset < 0)
        fail(path, "appended array " + arrayName(child) + " has no valid offset");
      if (fr.appendedStart < 0) fail(path, "array " + arrayName(child) + " is appended, but the file has no AppendedData");
      const std::uint64_t pos = std::uint64_t(fr.appendedStart) + std::uint64_t(offset);
      if (pos >= fr.fileSize) fail(path, "appended array " + arrayName(child) + " starts beyond the end of the file");
      if (!fr.appendedBase64) {
        checkAppendedRaw(in, pos, fr, child, path);
      } else if (!fr.compressed) {
        unsigned char head[8] = {};
        const std::uint64_t have = base64Bytes(in, std::int64_t(pos), false, head, fr.prefix);
        const std::uint64_t declared = decodePrefix(head, fr);
        if (have < fr.prefix || have - fr.prefix < declared)
          fail(path, "appended data of array " + arrayName(child) + " is truncated: it declares " +
                         std::to_string(declared) + " bytes and holds " +
                         std::to_string(have > fr.prefix ? have - fr.prefix : 0));
      }
    }
    checkArrays(child, in, fr, path);
  }
}

std::uint64_t typeBytes(const char* type) {
  if (!type) return 0;
  const std::string t = type;
  if (t == "Int8" || t == "UInt8") return 1;
  if (t == "Int16" || t == "UInt16") return 2;
  if (t == "Int32" || t == "UInt32" || t == "Float32") return 4;
  if (t == "Int64" || t == "UInt64" || t == "Float64") return 8;
  return 0;
}

// The decoded bytes a binary array holds: its size prefix, or compressed,
// its block table's total (blocks, block size, last block's size).
std::uint64_t blockBytes(const unsigned char* head, const Framing& fr) {
  if (!fr.compressed) return decodePrefix(head, fr);
  const std::uint64_t blocks = decodePrefix(head, fr), size = decodePrefix(head + fr.prefix, fr),
                      last = decodePrefix(head + 2 * fr.prefix, fr);
  return blocks == 0 ? 0 : (blocks - 1) * size + (last ? last : size);
}

// How many values array `e` holds in the file, or -1 where that is not told
// here (a format or encoding this does not know).
std::int64_t storedValues(vtkXMLDataElement* e, std::ifstream& in, const Framing& fr, std::uint64_t bytesPerValue) {
  const char* format = e->GetAttribute("format");
  if (!format) return -1;
  unsigned char head[24] = {};
  const std::size_t want = fr.compressed ? 3 * fr.prefix : fr.prefix;
  std::uint64_t bytes = 0;
  if (std::strcmp(format, "ascii") == 0) {
    in.clear();
    in.seekg(e->GetXMLByteIndex());
    for (char c; in.get(c) && c != '>';) {}
    std::int64_t words = 0;
    bool inWord = false;
    for (char c; in.get(c) && c != '<';) {
      const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
      words += !space && !inWord;
      inWord = !space;
    }
    return words;
  } else if (std::strcmp(format, "binary") == 0) {
    if (base64Bytes(in, e->GetXMLByteIndex(), true, head, want) < want) return -1;
    bytes = blockBytes(head, fr);
  } else if (std::strcmp(format, "appended") == 0) {
    long long offset = 0;
    if (!e->GetScalarAttribute("offset", offset) || offset < 0 || fr.appendedStart < 0) return -1;
    const std::int64_t pos = fr.appendedStart + offset;
    if (fr.appendedBase64) {
      if (base64Bytes(in, pos, false, head, want) < want) return -1;
    } else {
      in.clear();
      in.seekg(pos);
      if (!in.read(reinterpret_cast<char*>(head), std::streamsize(want))) return -1;
    }
    bytes = blockBytes(head, fr);
  } else {
    return -1;
  }
  return bytes % bytesPerValue ? -2 : std::int64_t(bytes / bytesPerValue);
}

// VTK reads as many values as a piece's points times the array's components
// and ignores the rest: 9-component tensors declared NumberOfComponents="6"
// were read as six-value tensors from the wrong offsets, and drawn. Every
// point array and the points must hold exactly what their piece needs.
void checkPointArraySizes(vtkXMLDataElement* data, std::ifstream& in, const Framing& fr, const std::string& path) {
  for (int p = 0; p < data->GetNumberOfNestedElements(); ++p) {
    vtkXMLDataElement* piece = data->GetNestedElement(p);
    if (std::strcmp(piece->GetName(), "Piece") != 0) continue;
    long long points = 0, e[6];
    if (!piece->GetScalarAttribute("NumberOfPoints", points)) {
      if (piece->GetVectorAttribute("Extent", 6, e) != 6) continue;
      points = 1;
      for (int k = 0; k < 3; ++k) points *= e[2 * k + 1] - e[2 * k] + 1;
    }
    for (int g = 0; g < piece->GetNumberOfNestedElements(); ++g) {
      vtkXMLDataElement* group = piece->GetNestedElement(g);
      if (std::strcmp(group->GetName(), "PointData") != 0 && std::strcmp(group->GetName(), "Points") != 0) continue;
      for (int a = 0; a < group->GetNumberOfNestedElements(); ++a) {
        vtkXMLDataElement* array = group->GetNestedElement(a);
        const std::uint64_t size = typeBytes(array->GetAttribute("type"));
        if (std::strcmp(array->GetName(), "DataArray") != 0 || size == 0) continue;
        const bool isPoints = std::strcmp(group->GetName(), "Points") == 0;
        const std::string name = isPoints ? "the points' array" : "array " + arrayName(array);
        int components = 1;
        array->GetScalarAttribute("NumberOfComponents", components);
        if (components < 1) fail(path, name + " has " + std::to_string(components) + " components");
        const std::int64_t stored = storedValues(array, in, fr, size);
        const long double need = (long double)points * components;
        if (stored == -1 || (long double)stored == need) continue;
        fail(path, name + " holds " +
                       (stored < 0 ? std::string("a part of a value") : std::to_string(stored) + " values") +
                       ", not the " + std::to_string(std::uint64_t(need)) + " of " + std::to_string(points) +
                       " points with " + std::to_string(components) + " components each");
      }
    }
  }
}

vtkXMLDataElement* findNested(vtkXMLDataElement* e, const char* name) {
  for (int k = 0; e && k < e->GetNumberOfNestedElements(); ++k)
    if (std::strcmp(e->GetNestedElement(k)->GetName(), name) == 0) return e->GetNestedElement(k);
  return nullptr;
}

// VTK sizes a structured dataset's arrays by its WholeExtent and fills in
// each piece: points no piece covers kept whatever the memory held (two of
// four tensors read as zeros, drawn). The pieces' boxes, cut at every piece
// boundary, must cover the whole; more cells than that check can afford
// are refused rather than trusted.
void checkPiecesCover(const long long whole[6], const std::vector<std::array<long long, 6>>& pieces,
                      const std::string& path) {
  std::vector<long long> cuts[3];
  std::uint64_t cells = 1;
  for (int k = 0; k < 3; ++k) {
    cuts[k] = {whole[2 * k], whole[2 * k + 1] + 1};
    for (const auto& e : pieces) cuts[k].insert(cuts[k].end(), {e[2 * k], e[2 * k + 1] + 1});
    std::sort(cuts[k].begin(), cuts[k].end());
    cuts[k].erase(std::unique(cuts[k].begin(), cuts[k].end()), cuts[k].end());
    cells *= cuts[k].size() - 1;
  }
  if (cells > (1u << 22))
    fail(path, std::to_string(pieces.size()) + " pieces are too many to check that they cover the WholeExtent");
  std::vector<char> covered(std::size_t(cells), 0);
  auto index = [&](int k, long long v) {
    return std::size_t(std::lower_bound(cuts[k].begin(), cuts[k].end(), v) - cuts[k].begin());
  };
  const std::size_t nx = cuts[0].size() - 1, ny = cuts[1].size() - 1;
  std::uint64_t work = 0;
  for (const auto& e : pieces) {
    work += std::uint64_t(index(0, e[1] + 1) - index(0, e[0])) * (index(1, e[3] + 1) - index(1, e[2])) *
            (index(2, e[5] + 1) - index(2, e[4]));
    if (work > (1u << 26))
      fail(path, std::to_string(pieces.size()) + " pieces are too many to check that they cover the WholeExtent");
  }
  for (const auto& e : pieces)
    for (std::size_t z = index(2, e[4]); z < index(2, e[5] + 1); ++z)
      for (std::size_t y = index(1, e[2]); y < index(1, e[3] + 1); ++y)
        for (std::size_t x = index(0, e[0]); x < index(0, e[1] + 1); ++x) covered[x + nx * (y + ny * z)] = 1;
  if (std::find(covered.begin(), covered.end(), 0) != covered.end())
    fail(path, "its pieces leave part of the WholeExtent uncovered: those points would be left unset");
}

// VTK reads numeric attributes with a stream too (GetVectorAttribute,
// GetScalarAttribute): Origin="0 0 1,5" read as z = 1, NumberOfComponents="9x"
// as 9. Each such attribute's words must be whole numbers, integers where
// VTK reads integers (util/strict_number.h).
void checkNumericAttributes(vtkXMLDataElement* e, const std::string& path) {
  static const char* const kIntegers[] = {"WholeExtent",   "Extent",        "NumberOfPoints", "NumberOfCells",
                                          "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys",
                                          "NumberOfComponents", "NumberOfTuples", "offset"};
  static const char* const kReals[] = {"Origin", "Spacing", "Direction"};
  auto check = [&](const char* name, bool integral) {
    const char* value = e->GetAttribute(name);
    if (!value) return;
    const std::string_view v(value);
    for (std::size_t k = 0; k < v.size();) {
      while (k < v.size() && std::isspace(static_cast<unsigned char>(v[k]))) ++k;
      const std::size_t from = k;
      while (k < v.size() && !std::isspace(static_cast<unsigned char>(v[k]))) ++k;
      const std::string_view word = v.substr(from, k - from);
      if (word.empty() || (integral ? util::parseInteger(word).has_value() : util::parseNumber(word).has_value()))
        continue;
      fail(path, std::string(e->GetName()) + " attribute " + name + "=\"" + value + "\" holds \"" + std::string(word) +
                     "\", which is not " + (integral ? "an integer" : "a number"));
    }
  };
  for (const char* name : kIntegers) check(name, true);
  for (const char* name : kReals) check(name, false);
  for (int k = 0; k < e->GetNumberOfNestedElements(); ++k) checkNumericAttributes(e->GetNestedElement(k), path);
}

// A structured dataset's numbers VTK would otherwise replace by defaults
// when they do not parse (Spacing="nan 1 1" became spacing 1), and pieces
// outside the whole extent, whose points VTK leaves uninitialised.
void checkStructured(vtkXMLDataElement* root, const std::string& path) {
  const char* type = root->GetAttribute("type");
  if (!type) return;
  vtkXMLDataElement* data = findNested(root, type);
  if (!data) return;
  auto finite = [&](const char* name, int n) {
    if (!data->GetAttribute(name)) return;
    double v[9];
    if (data->GetVectorAttribute(name, n, v) != n || !std::all_of(v, v + n, [](double x) { return std::isfinite(x); }))
      fail(path, std::string(type) + " " + name + " is not " + std::to_string(n) + " finite numbers");
  };
  finite("Origin", 3);
  finite("Spacing", 3);
  finite("Direction", 9);
  long long whole[6];
  if (!data->GetAttribute("WholeExtent")) return;
  if (data->GetVectorAttribute("WholeExtent", 6, whole) != 6) fail(path, "WholeExtent is not six integers");
  std::vector<std::array<long long, 6>> pieces;
  for (int p = 0; p < data->GetNumberOfNestedElements(); ++p) {
    vtkXMLDataElement* piece = data->GetNestedElement(p);
    long long e[6];
    if (std::strcmp(piece->GetName(), "Piece") != 0) continue;
    if (piece->GetVectorAttribute("Extent", 6, e) != 6) fail(path, "a piece's Extent is not six integers");
    for (int k = 0; k < 3; ++k)
      if (e[2 * k] < whole[2 * k] || e[2 * k + 1] > whole[2 * k + 1] || e[2 * k] > e[2 * k + 1])
        fail(path, "a piece's Extent lies outside the WholeExtent: its points would be left unset");
    pieces.push_back({e[0], e[1], e[2], e[3], e[4], e[5]});
  }
  checkPiecesCover(whole, pieces, path);
}

}  // namespace

std::uint64_t xmlPoints(vtkAlgorithm* reader, const std::string& path) {
  vtkInformation* info = reader->GetOutputInformation(0);
  if (info && info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT())) {
    int e[6];
    info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), e);
    std::uint64_t points = 1;
    for (int k = 0; k < 3; ++k) {
      const std::int64_t n = std::int64_t(e[2 * k + 1]) - std::int64_t(e[2 * k]) + 1;
      if (n < 1 || n > INT32_MAX) fail(path, "extent " + std::to_string(e[2 * k]) + ".." + std::to_string(e[2 * k + 1]) +
                                               " is empty or too long");
      points *= std::uint64_t(n);
    }
    return points;
  }
  std::uint64_t points = 0;
  vtkXMLDataElement* root = rootOf(reader);
  for (int d = 0; root && d < root->GetNumberOfNestedElements(); ++d) {
    vtkXMLDataElement* data = root->GetNestedElement(d);
    for (int p = 0; p < data->GetNumberOfNestedElements(); ++p) {
      vtkXMLDataElement* piece = data->GetNestedElement(p);
      vtkIdType n = 0;
      if (std::string(piece->GetName()) != "Piece" || !piece->GetScalarAttribute("NumberOfPoints", n)) continue;
      if (n < 0) fail(path, "a piece has a negative NumberOfPoints");
      points += std::uint64_t(n);
    }
  }
  return points;
}

bool xmlCompressed(vtkAlgorithm* reader) {
  vtkXMLDataElement* root = rootOf(reader);
  return root && root->GetAttribute("compressor");
}


void checkXmlStructure(vtkAlgorithm* reader, const std::string& path) {
  vtkXMLDataElement* root = rootOf(reader);
  if (!root) return;
  checkNumericAttributes(root, path);
  checkStructured(root, path);
  Framing fr;
  fr.compressed = root->GetAttribute("compressor") != nullptr;
  const char* order = root->GetAttribute("byte_order");
  fr.bigEndian = order && std::strcmp(order, "BigEndian") == 0;
  const char* type = root->GetAttribute("header_type");
  fr.prefix = type && std::strcmp(type, "UInt64") == 0 ? 8 : 4;
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) fail(path, "cannot open file");
  fr.fileSize = std::uint64_t(st.st_size);
  std::ifstream in(path, std::ios::binary);
  if (vtkXMLDataElement* appended = findNested(root, "AppendedData")) {
    const char* encoding = appended->GetAttribute("encoding");
    fr.appendedBase64 = !encoding || std::strcmp(encoding, "raw") != 0;
    in.seekg(appended->GetXMLByteIndex());
    for (char c; in.get(c) && c != '>';) {}
    for (char c; in.get(c);)
      if (c == '_') {
        fr.appendedStart = std::int64_t(in.tellg());
        break;
      }
  }
  checkArrays(root, in, fr, path);
  const char* dataType = root->GetAttribute("type");
  if (vtkXMLDataElement* data = dataType ? findNested(root, dataType) : nullptr)
    checkPointArraySizes(data, in, fr, path);
}

}  // namespace tg::io
