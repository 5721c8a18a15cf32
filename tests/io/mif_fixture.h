#pragma once
// Writes small MRtrix images for the tests, independently of the reader: each
// value's byte offset is computed from the layout's strides directly (the
// reader walks the file in order instead).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace tg::test {

struct MifFixture {
  int dims[3] = {2, 3, 4};
  double vox[3] = {1.5, 2, 2.5};
  // Signed stride order per axis (i j k component), as the header spells it.
  std::array<std::string, 4> layout{"+1", "+2", "+3", "+0"};
  std::string datatype = "Float32LE";
  std::vector<std::array<double, 4>> transform{{1, 0, 0, 10}, {0, 1, 0, 20}, {0, 0, 1, 30}};
  std::string scaling;                     // "" or "offset,scale"
  std::string extra;                       // more header lines, each ending in '\n'
  std::vector<std::array<double, 6>> mrtrix;  // per voxel, i fastest: xx yy zz xy xz yz as stored
  std::size_t voxels() const { return std::size_t(dims[0] * dims[1] * dims[2]); }
  // Distinct values that every data type holds exactly.
  void fillDistinct(bool isSigned) {
    mrtrix.assign(voxels(), {});
    for (std::size_t v = 0; v < voxels(); ++v)
      for (int c = 0; c < 6; ++c) mrtrix[v][std::size_t(c)] = double(6 * v + std::size_t(c)) - (isSigned ? 72.0 : 0.0);
  }
};

inline std::string slurpBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The bytes of value x as `datatype` ("Int16BE", "Float64LE", "Float32"...).
inline std::string encodeMifValue(const std::string& datatype, double x) {
  std::string t = datatype;
  bool big = false;
  if (t.ends_with("LE") || t.ends_with("BE")) {
    big = t.ends_with("BE");
    t.resize(t.size() - 2);
  }
  std::string b;
  auto put = [&](const auto v) {
    b.resize(sizeof v);
    std::memcpy(b.data(), &v, sizeof v);
    if (big != (std::endian::native == std::endian::big)) std::reverse(b.begin(), b.end());
  };
  if (t == "Int8") put(std::int8_t(x));
  else if (t == "UInt8") put(std::uint8_t(x));
  else if (t == "Int16") put(std::int16_t(x));
  else if (t == "UInt16") put(std::uint16_t(x));
  else if (t == "Int32") put(std::int32_t(x));
  else if (t == "UInt32") put(std::uint32_t(x));
  else if (t == "Int64") put(std::int64_t(x));
  else if (t == "UInt64") put(std::uint64_t(x));
  else if (t == "Float32") put(float(x));
  else if (t == "Float64") put(x);
  return b;
}

// The data block: value (voxel, c) at sum over axes of position * stride,
// strides from the layout's ranks, a descending axis counted from its end.
inline std::string mifData(const MifFixture& fx) {
  const long long dim[4] = {fx.dims[0], fx.dims[1], fx.dims[2], 6};
  long long stride[4] = {0, 0, 0, 0};
  bool down[4];
  int rank[4];
  for (int a = 0; a < 4; ++a) {
    down[a] = fx.layout[std::size_t(a)][0] == '-';
    rank[a] = std::abs(std::stoi(fx.layout[std::size_t(a)]));
  }
  for (int a = 0; a < 4; ++a) {
    stride[a] = 1;
    for (int b = 0; b < 4; ++b)
      if (rank[b] < rank[a]) stride[a] *= dim[b];
  }
  const std::size_t tsize = encodeMifValue(fx.datatype, 0).size();
  std::string data(fx.voxels() * 6 * tsize, '\0');
  for (long long k = 0; k < dim[2]; ++k)
    for (long long j = 0; j < dim[1]; ++j)
      for (long long i = 0; i < dim[0]; ++i)
        for (long long c = 0; c < 6; ++c) {
          const long long idx[4] = {i, j, k, c};
          long long off = 0;
          for (int a = 0; a < 4; ++a) off += (down[a] ? dim[a] - 1 - idx[a] : idx[a]) * stride[a];
          const std::size_t v = std::size_t(i + dim[0] * (j + dim[1] * k));
          const std::string bytes = encodeMifValue(fx.datatype, fx.mrtrix[v][std::size_t(c)]);
          std::copy(bytes.begin(), bytes.end(), data.begin() + std::ptrdiff_t(std::size_t(off) * tsize));
        }
  return data;
}

inline std::string mifHeader(const MifFixture& fx, const std::string& fileEntry) {
  std::string h = "mrtrix image\ndim: " + std::to_string(fx.dims[0]) + "," + std::to_string(fx.dims[1]) + "," +
                  std::to_string(fx.dims[2]) + ",6\n";
  char vox[128];
  std::snprintf(vox, sizeof vox, "vox: %.17g,%.17g,%.17g,nan\n", fx.vox[0], fx.vox[1], fx.vox[2]);
  h += vox;
  h += "layout: " + fx.layout[0] + "," + fx.layout[1] + "," + fx.layout[2] + "," + fx.layout[3] + "\n";
  h += "datatype: " + fx.datatype + "\n";
  for (const auto& row : fx.transform) {
    char line[160];
    std::snprintf(line, sizeof line, "transform: %.17g, %.17g, %.17g, %.17g\n", row[0], row[1], row[2], row[3]);
    h += line;
  }
  if (!fx.scaling.empty()) h += "scaling: " + fx.scaling + "\n";
  h += fx.extra;
  return h + fileEntry + "\nEND\n";
}

// A .mif: the header, padding to `offset`, then the data.
inline void writeMif(const std::filesystem::path& p, const MifFixture& fx) {
  std::string head = mifHeader(fx, "file: . 0000");
  const std::size_t offset = (head.size() + 15) / 16 * 16;
  char entry[32];
  std::snprintf(entry, sizeof entry, "file: . %04zu", offset);
  head = mifHeader(fx, entry);  // same length: the offset keeps its four digits
  head.resize(offset, '\0');
  std::ofstream(p, std::ios::binary) << head << mifData(fx);
}

// A .mih naming `dataName` (beside it) with the data at `offset`.
inline void writeMih(const std::filesystem::path& p, const MifFixture& fx, const std::string& dataName,
                     std::size_t offset) {
  std::ofstream(p, std::ios::binary) << mifHeader(fx, "file: " + dataName + " " + std::to_string(offset));
  std::ofstream(p.parent_path() / dataName, std::ios::binary) << std::string(offset, 'x') << mifData(fx);
}

}  // namespace tg::test
