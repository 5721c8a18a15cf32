#include "io/vtk_xml_checks.h"

#include <cstring>
#include <fstream>

#include <vtkAlgorithm.h>
#include <vtkInformation.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLReader.h>

#include "io/tensor_field.h"

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

// The base64 text of the element starting at `at`: its first `prefix` bytes
// decoded into `head`, and the number of bytes the whole text decodes to.
std::uint64_t inlineBytes(std::ifstream& in, std::int64_t at, unsigned char* head, std::size_t prefix) {
  in.clear();
  in.seekg(at);
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

void checkArrays(vtkXMLDataElement* e, std::ifstream& in, std::size_t prefix, bool bigEndian, const std::string& path) {
  for (int k = 0; k < e->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* child = e->GetNestedElement(k);
    const char* format = child->GetAttribute("format");
    if (std::strcmp(child->GetName(), "DataArray") == 0 && format && std::strcmp(format, "binary") == 0) {
      unsigned char head[8] = {};
      const std::uint64_t have = inlineBytes(in, child->GetXMLByteIndex(), head, prefix);
      std::uint64_t declared = 0;  // the prefix is in the file's byte order
      for (std::size_t b = 0; b < prefix; ++b) declared = (declared << 8) | head[bigEndian ? b : prefix - 1 - b];
      const char* name = child->GetAttribute("Name");
      if (have < prefix || have - prefix < declared)
        fail(path, "inline data of array \"" + std::string(name ? name : "?") + "\" is truncated: it declares " +
                       std::to_string(declared) + " bytes and holds " + std::to_string(have > prefix ? have - prefix : 0));
    }
    checkArrays(child, in, prefix, bigEndian, path);
  }
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


void checkInlineBinary(vtkAlgorithm* reader, const std::string& path) {
  vtkXMLDataElement* root = rootOf(reader);
  if (!root || root->GetAttribute("compressor")) return;
  const char* order = root->GetAttribute("byte_order");
  const char* type = root->GetAttribute("header_type");
  const std::size_t prefix = type && std::strcmp(type, "UInt64") == 0 ? 8 : 4;
  std::ifstream in(path, std::ios::binary);
  checkArrays(root, in, prefix, order && std::strcmp(order, "BigEndian") == 0, path);
}

}  // namespace tg::io
