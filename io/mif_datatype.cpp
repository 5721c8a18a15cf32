#include "io/mif_datatype.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "io/tensor_field.h"

namespace tg::io {
namespace {

template <class U>
U swapBytes(U u) {
  if constexpr (sizeof(U) == 2) return __builtin_bswap16(u);
  else if constexpr (sizeof(U) == 4) return __builtin_bswap32(u);
  else if constexpr (sizeof(U) == 8) return __builtin_bswap64(u);
  else return u;
}

template <class T, bool Swap>
void convert(const char* src, std::size_t n, double* dst) {
  using U = std::conditional_t<sizeof(T) == 1, std::uint8_t,
                               std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                                  std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
  for (std::size_t i = 0; i < n; ++i) {
    U u;
    std::memcpy(&u, src + i * sizeof(T), sizeof(U));
    if constexpr (Swap) u = swapBytes(u);
    dst[i] = double(std::bit_cast<T>(u));
  }
}

template <class T>
MifConvert converter(bool swap) {
  return swap ? &convert<T, true> : &convert<T, false>;
}

}  // namespace

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
  MifDataType d{std::string(text), 0, nullptr};
  if (base == "int8") d = {d.name, 1, converter<std::int8_t>(false)};
  else if (base == "uint8") d = {d.name, 1, converter<std::uint8_t>(false)};
  else if (base == "int16") d = {d.name, 2, converter<std::int16_t>(swap)};
  else if (base == "uint16") d = {d.name, 2, converter<std::uint16_t>(swap)};
  else if (base == "int32") d = {d.name, 4, converter<std::int32_t>(swap)};
  else if (base == "uint32") d = {d.name, 4, converter<std::uint32_t>(swap)};
  else if (base == "int64") d = {d.name, 8, converter<std::int64_t>(swap)};
  else if (base == "uint64") d = {d.name, 8, converter<std::uint64_t>(swap)};
  else if (base == "float32") d = {d.name, 4, converter<float>(swap)};
  else if (base == "float64") d = {d.name, 8, converter<double>(swap)};
  else if (base == "bit" || base.starts_with("cfloat"))
    fail("datatype " + std::string(text) + " is not supported; tensors need real numbers");
  else fail("datatype \"" + std::string(text) + "\" is not an MRtrix data type");
  // "Int8LE" and the like name no real type.
  if (d.bytes == 1 && base != t) fail("datatype \"" + std::string(text) + "\" is not an MRtrix data type");
  return d;
}


}  // namespace tg::io
