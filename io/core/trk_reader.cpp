// TrackVis .trk (trackvis.org/docs/?subsect=fileformat): a 1000-byte header,
// then per streamline an int32 point count, its points (x y z and the
// header's scalars, float32) and its properties. The byte order is the one
// that makes hdr_size 1000. Points are in "voxmm" (voxel index times voxel
// size, from the corner of the first voxel) and are taken to RAS+ mm as
// nibabel.streamlines does (trkToWorld). Nothing is allocated from a count:
// each streamline's size is checked against what is left of the file first.
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "io/core/format_table.h"
#include "io/core/tract_builder.h"
#include "io/core/tract_reader.h"

namespace tg::io {
namespace {

constexpr std::size_t kHeaderBytes = 1000;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readTracts: " + path + ": " + what);
}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

using Mat4 = std::array<double, 16>;  // row-major

Mat4 identity() {
  Mat4 m{};
  m[0] = m[5] = m[10] = m[15] = 1.0;
  return m;
}

Mat4 mul(const Mat4& a, const Mat4& b) {
  Mat4 c{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) c[4 * i + j] += a[4 * i + k] * b[4 * k + j];
  return c;
}

double det3(const double m[9]) {
  return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
}

// The orthogonal factor of m's polar decomposition (Higham's iteration,
// X <- (X + X^-T) / 2), which is nibabel's P Q^T from the SVD.
void polarFactor(double m[9]) {
  for (int it = 0; it < 100; ++it) {
    const double d = det3(m);
    // The inverse's transpose is the cofactor matrix over the determinant.
    const double cof[9] = {m[4] * m[8] - m[5] * m[7], m[5] * m[6] - m[3] * m[8], m[3] * m[7] - m[4] * m[6],
                           m[2] * m[7] - m[1] * m[8], m[0] * m[8] - m[2] * m[6], m[1] * m[6] - m[0] * m[7],
                           m[1] * m[5] - m[2] * m[4], m[2] * m[3] - m[0] * m[5], m[0] * m[4] - m[1] * m[3]};
    double change = 0.0;
    for (int k = 0; k < 9; ++k) {
      const double next = 0.5 * (m[k] + cof[k] / d);
      change = std::max(change, std::abs(next - m[k]));
      m[k] = next;
    }
    if (change < 1e-15) return;
  }
}

struct AxisFlip {
  int axis;
  int flip;  // +1 or -1
};

}  // namespace

TrkTransform trkToWorld(const float voxToRas[16], const char voxelOrder[4], const std::int16_t dims[3],
                        const float voxelSizes[3]) {
  TrkTransform t;
  Mat4 v2r;
  for (int k = 0; k < 16; ++k) v2r[std::size_t(k)] = double(voxToRas[k]);
  for (double v : v2r)
    if (!std::isfinite(v)) {
      t.problem = "vox_to_ras holds a NaN or Inf";
      return t;
    }
  // The axes vox_to_ras points its voxel axes along (nibabel's io_orientation):
  // columns normalised, the polar factor's largest entry per column, in order.
  double rs[9];
  for (int j = 0; j < 3; ++j) {
    double norm = 0.0;
    for (int i = 0; i < 3; ++i) norm += v2r[std::size_t(4 * i + j)] * v2r[std::size_t(4 * i + j)];
    norm = norm > 0.0 ? std::sqrt(norm) : 1.0;
    for (int i = 0; i < 3; ++i) rs[3 * i + j] = v2r[std::size_t(4 * i + j)] / norm;
  }
  if (!(std::abs(det3(rs)) > 1e-9)) {
    t.problem = "vox_to_ras is singular: its voxel axes have no directions";
    return t;
  }
  polarFactor(rs);
  AxisFlip affineOrnt[3];
  for (int j = 0; j < 3; ++j) {
    int best = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(rs[3 * i + j]) > std::abs(rs[3 * best + j])) best = i;
    affineOrnt[j] = {best, rs[3 * best + j] < 0 ? -1 : 1};
    for (int k = 0; k < 3; ++k) rs[3 * best + k] = 0.0;
  }
  // The header's voxel order: one of L/R, P/A, I/S per axis (nibabel's
  // axcodes2ornt); none given is TrackVis's default, LPS.
  std::string order;
  for (int k = 0; k < 4 && voxelOrder[k]; ++k) order.push_back(char(std::toupper(static_cast<unsigned char>(voxelOrder[k]))));
  if (order.empty()) order = "LPS";
  AxisFlip headerOrnt[3];
  bool seen[3] = {false, false, false};
  bool valid = order.size() == 3;
  for (std::size_t k = 0; valid && k < 3; ++k) {
    const char c = order[k];
    const int axis = c == 'L' || c == 'R' ? 0 : c == 'P' || c == 'A' ? 1 : c == 'I' || c == 'S' ? 2 : -1;
    valid = axis >= 0 && !seen[axis];
    if (valid) {
      seen[axis] = true;
      headerOrnt[k] = {axis, c == 'R' || c == 'A' || c == 'S' ? 1 : -1};
    }
  }
  if (!valid) {
    t.problem = "voxel order \"" + order + "\" is not one of L/R, P/A and I/S for each axis";
    return t;
  }
  // ornt_transform(header, affine), then inv_ornt_aff over the dimensions.
  AxisFlip ornt[3];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (headerOrnt[i].axis == affineOrnt[j].axis) ornt[i] = {j, headerOrnt[i].flip == affineOrnt[j].flip ? 1 : -1};
  Mat4 reorient{};
  reorient[15] = 1.0;
  for (int i = 0; i < 3; ++i) {
    reorient[std::size_t(4 * i + ornt[i].axis)] = ornt[i].flip;
    reorient[std::size_t(4 * i + 3)] = ornt[i].flip < 0 ? double(dims[i]) - 1.0 : 0.0;
  }
  Mat4 toVoxel = identity();
  for (int i = 0; i < 3; ++i) {
    toVoxel[std::size_t(5 * i)] = 1.0 / double(voxelSizes[i]);
    toVoxel[std::size_t(4 * i + 3)] = -0.5;  // the corner of voxel 0 to its centre
  }
  const Mat4 m = mul(v2r, mul(reorient, toVoxel));
  // nibabel hands the affine over in single precision.
  for (std::size_t k = 0; k < 16; ++k) t.voxmmToRas[k] = double(float(m[k]));
  t.ok = true;
  return t;
}

TractData readTrk(const std::string& path, std::uint64_t memoryBudget, const PromiseFn& promise) {
  const std::uint64_t size = checkInputFile("readTracts", path);
  if (size < kHeaderBytes)
    fail(path, "too short for a TrackVis file (" + std::to_string(size) + " bytes; the header alone is 1000)");
  std::unique_ptr<std::FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
  if (!f) fail(path, "cannot open the file");
  unsigned char h[kHeaderBytes];
  if (std::fread(h, 1, kHeaderBytes, f.get()) != kHeaderBytes) fail(path, "the header could not be read");
  if (std::memcmp(h, "TRACK", 5) != 0) fail(path, "not a TrackVis file (it does not begin with \"TRACK\")");
  std::int32_t hdrSize;
  std::memcpy(&hdrSize, h + 996, 4);
  const bool swap = hdrSize != 1000;
  if (swap && std::int32_t(__builtin_bswap32(std::uint32_t(hdrSize))) != 1000)
    fail(path, "hdr_size is " + std::to_string(hdrSize) + " in either byte order, not 1000: not a TrackVis header");
  auto i16 = [&](std::size_t at) {
    std::int16_t v;
    std::memcpy(&v, h + at, 2);
    return swap ? std::int16_t(__builtin_bswap16(std::uint16_t(v))) : v;
  };
  auto i32 = [&](const unsigned char* p) {
    std::int32_t v;
    std::memcpy(&v, p, 4);
    return swap ? std::int32_t(__builtin_bswap32(std::uint32_t(v))) : v;
  };
  auto f32 = [&](const unsigned char* p) { return std::bit_cast<float>(i32(p)); };
  const std::int32_t version = i32(h + 992), count = i32(h + 988);
  if (version != 1 && version != 2)
    fail(path, "version " + std::to_string(version) + "; TrackVis files are version 1 or 2");
  const std::int16_t dims[3] = {i16(6), i16(8), i16(10)};
  float voxelSizes[3], voxToRas[16];
  for (int k = 0; k < 3; ++k) voxelSizes[k] = f32(h + 12 + 4 * k);
  for (int k = 0; k < 16; ++k) voxToRas[k] = version == 1 ? 0.0f : f32(h + 440 + 4 * k);
  const std::int16_t nScalars = i16(36), nProperties = i16(238);
  for (int k = 0; k < 3; ++k) {
    if (dims[k] < 0) fail(path, "dimension " + std::to_string(k) + " is " + std::to_string(dims[k]) + ", negative");
    if (!(voxelSizes[k] > 0.0f && std::isfinite(voxelSizes[k])))
      fail(path, "voxel size " + std::to_string(k) + " is " + std::to_string(voxelSizes[k]) +
                     ", not a positive finite number: the points cannot be placed");
  }
  if (nScalars < 0 || nProperties < 0)
    fail(path, "negative counts of scalars per point (" + std::to_string(nScalars) + ") or properties (" +
                   std::to_string(nProperties) + ")");
  if (count < 0) fail(path, "n_count is " + std::to_string(count) + ", negative");
  TractData out;
  out.path = path;
  if (voxToRas[15] == 0.0f) {
    // nibabel's reading of a header that records none: the identity, with a warning.
    for (int k = 0; k < 16; ++k) voxToRas[k] = k % 5 == 0 ? 1.0f : 0.0f;
    out.warning = "the header records no vox_to_ras; taken as the identity, as nibabel does";
  }
  char order[4];
  std::memcpy(order, h + 948, 4);
  const TrkTransform t = trkToWorld(voxToRas, order, dims, voxelSizes);
  if (!t.ok) fail(path, t.problem);

  const std::uint64_t bytes = size - kHeaderBytes;
  const std::uint64_t perPoint = 4 * (3 + std::uint64_t(nScalars)), perLine = 4 * std::uint64_t(nProperties);
  // Our copy: 12 bytes a point, which takes at least 12 of the file.
  const std::uint64_t need = bytes + bytes / 2 + (16 << 20);
  if (memoryBudget && need > memoryBudget)
    fail(path, "reading would need about " + std::to_string(need >> 20) + " MiB, more than the " +
                   std::to_string(memoryBudget >> 20) + " MiB this load may use");
  if (promise) promise(bytes, need);
  TractBuilder build(out, "readTracts: " + path);
  const auto& a = t.voxmmToRas;
  std::vector<unsigned char> buf;
  std::uint64_t left = bytes, lines = 0;
  while (count == 0 ? left > 0 : lines < std::uint64_t(count)) {
    const std::string which = "streamline " + std::to_string(lines);
    if (left < 4)
      fail(path, which + (left ? " has no whole point count" : " is missing") + " (the header counts " +
                     std::to_string(count) + "): truncated");
    unsigned char n4[4];
    if (std::fread(n4, 1, 4, f.get()) != 4) fail(path, "the data could not be read: truncated");
    left -= 4;
    const std::int32_t n = i32(n4);
    if (n < 0) fail(path, which + " has " + std::to_string(n) + " points");
    const std::uint64_t want = std::uint64_t(n) * perPoint + perLine;
    if (want > left)
      fail(path, which + "'s " + std::to_string(n) + " points need " + std::to_string(want) + " bytes, and " +
                     std::to_string(left) + " are left: truncated, or the count is wrong");
    buf.resize(std::size_t(want));
    if (want && std::fread(buf.data(), 1, std::size_t(want), f.get()) != want)
      fail(path, "the data could not be read: truncated");
    left -= want;
    for (std::int32_t k = 0; k < n; ++k) {
      const unsigned char* p = &buf[std::size_t(k) * std::size_t(perPoint)];
      const double x = f32(p), y = f32(p + 4), z = f32(p + 8);
      build.point(a[0] * x + a[1] * y + a[2] * z + a[3], a[4] * x + a[5] * y + a[6] * z + a[7],
                  a[8] * x + a[9] * y + a[10] * z + a[11]);
    }
    build.end(true);
    ++lines;
  }
  if (left)
    fail(path, std::to_string(left) + " bytes after the " + std::to_string(count) +
                   " streamlines the header counts: the count is wrong, or the file is not one TrackVis file");
  out.description = "TrackVis tracks (version " + std::to_string(version) + (swap ? ", big-endian" : "") + "), " +
                    std::to_string(out.streamlineCount()) + " streamlines, " + std::to_string(out.pointCount()) +
                    " points";
  return out;
}

}  // namespace tg::io
