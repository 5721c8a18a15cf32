#pragma once
// MRtrix data types: their names in a header, their sizes, and a converter
// from the file's bytes (either byte order) to doubles. Used by
// io/mif_reader.cpp only; apart so that the reader stays one job.
#include <cstddef>
#include <string>
#include <string_view>

namespace tg::io {

using MifConvert = void (*)(const char* src, std::size_t n, double* dst);

struct MifDataType {
  std::string name;  // as the header spells it
  int bytes = 0;
  MifConvert convert = nullptr;
};

// MRtrix's names, case-insensitive; a multi-byte type without LE/BE is the
// machine's own order, as MRtrix reads it. InputError("readMif: path: ...")
// for Bit and complex types and anything else.
MifDataType parseMifDataType(const std::string& path, std::string_view text);

}  // namespace tg::io
