#pragma once
// MRtrix data types: their names in a header, their sizes, and how the
// file's bytes are converted to doubles (io/core/raw_samples.h, either byte
// order). Used by io/core/mif_reader.cpp only; apart so that the reader stays one
// job.
#include <cstddef>
#include <string>
#include <string_view>

#include "io/core/raw_samples.h"

namespace tg::io {

struct MifDataType {
  std::string name;  // as the header spells it
  RawType type = RawType::F32;  // its size: rawTypeBytes(type)
  bool swap = false;  // stored in the other byte order
};

// MRtrix's names, case-insensitive; a multi-byte type without LE/BE is the
// machine's own order, as MRtrix reads it. InputError("readMif: path: ...")
// for Bit and complex types and anything else.
MifDataType parseMifDataType(const std::string& path, std::string_view text);

}  // namespace tg::io
