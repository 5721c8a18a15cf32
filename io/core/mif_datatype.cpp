#include "io/core/mif_datatype.h"

#include <algorithm>
#include <bit>
#include <cctype>

#include "io/field/tensor_field.h"

namespace tg::io {

MifDataType parseMifDataType(const std::string& path, std::string_view text) {
  auto fail = [&](const std::string& what) { throw InputError("readMif: " + path + ": " + what); };
  std::string t(text);
  std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  std::string base = t;
  bool big = std::endian::native == std::endian::big;
  if (t.ends_with("le") || t.ends_with("be")) {
    big = t.ends_with("be");
    base = t.substr(0, t.size() - 2);
  }
  const bool swap = big != (std::endian::native == std::endian::big);
  static const struct {
    const char* base;
    RawType type;
  } kTypes[] = {{"int8", RawType::I8},     {"uint8", RawType::U8},     {"int16", RawType::I16},
                {"uint16", RawType::U16},  {"int32", RawType::I32},    {"uint32", RawType::U32},
                {"int64", RawType::I64},   {"uint64", RawType::U64},   {"float32", RawType::F32},
                {"float64", RawType::F64}};
  const auto known = std::find_if(std::begin(kTypes), std::end(kTypes), [&](const auto& k) { return base == k.base; });
  if (known == std::end(kTypes) && (base == "bit" || base.starts_with("cfloat")))
    fail("datatype " + std::string(text) + " is not supported; tensors need real numbers");
  if (known == std::end(kTypes)) fail("datatype \"" + std::string(text) + "\" is not an MRtrix data type");
  const MifDataType d{std::string(text), known->type, rawTypeBytes(known->type) > 1 && swap};
  // "Int8LE" and the like name no real type.
  if (rawTypeBytes(d.type) == 1 && base != t) fail("datatype \"" + std::string(text) + "\" is not an MRtrix data type");
  return d;
}

}  // namespace tg::io
