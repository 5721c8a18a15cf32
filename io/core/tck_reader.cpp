// MRtrix .tck (mrtrix.org, "Tracks file format"): a text header from
// "mrtrix tracks" to "END", then from `file: . OFFSET` point triplets in the
// header's datatype, each streamline ended by a NaN triplet and the file by
// an Inf triplet. Points are in scanner space (RAS+ mm), the world as is.
// Nothing is allocated from the header's `count`: the points are bounded by
// the file's size, and read in chunks.
#include <bit>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "io/core/format_table.h"
#include "io/core/tract_builder.h"
#include "io/core/tract_reader.h"
#include "util/strict_number.h"

namespace tg::io {
namespace {

constexpr std::size_t kMaxHeaderBytes = 1 << 20;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readTracts: " + path + ": " + what);
}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

template <class T>
T fromBytes(const unsigned char* p, bool bigEndian) {
  using U = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
  U u;
  std::memcpy(&u, p, sizeof u);
  if (bigEndian != (std::endian::native == std::endian::big)) u = sizeof(U) == 4 ? U(__builtin_bswap32(std::uint32_t(u))) : U(__builtin_bswap64(u));
  return std::bit_cast<T>(u);
}

}  // namespace

TractData readTck(const std::string& path, std::uint64_t memoryBudget, const PromiseFn& promise) {
  const std::uint64_t size = checkInputFile("readTracts", path);
  std::unique_ptr<std::FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
  if (!f) fail(path, "cannot open the file");
  // The header, a line at a time, within its first MiB.
  std::string line;
  std::uint64_t at = 0;
  auto nextLine = [&]() -> bool {
    line.clear();
    for (int c; (c = std::fgetc(f.get())) != EOF;) {
      if (++at > kMaxHeaderBytes) fail(path, "no END line in the header's first MiB");
      if (c == '\n') return true;
      if (c == '\0') fail(path, "the header holds a NUL byte: not an MRtrix tracks file, or not its header");
      line.push_back(char(c));
    }
    return !line.empty();
  };
  if (!nextLine() || trimmed(line) != "mrtrix tracks")
    fail(path, "not an MRtrix tracks file (its first line is not \"mrtrix tracks\")");
  std::string datatype, file;
  bool ended = false;
  for (int lineNo = 2; nextLine(); ++lineNo) {
    const std::string t = trimmed(line);
    if (t.empty()) continue;
    if (t == "END") {
      ended = true;
      break;
    }
    const auto colon = t.find(':');
    if (colon == std::string::npos)
      fail(path, "header line " + std::to_string(lineNo) + " is not \"key: value\"");
    const std::string key = trimmed(t.substr(0, colon)), value = trimmed(t.substr(colon + 1));
    if ((key == "datatype" && !datatype.empty()) || (key == "file" && !file.empty()))
      fail(path, "the header gives \"" + key + "\" twice");
    if (key == "datatype") datatype = value;
    if (key == "file") file = value;
  }
  if (!ended) fail(path, "the header has no END line: truncated, or not an MRtrix tracks file");
  const std::uint64_t headerEnd = at;
  if (datatype.empty()) fail(path, "the header gives no datatype");
  const bool f64 = datatype.starts_with("Float64");
  if (!(datatype == "Float32LE" || datatype == "Float32BE" || datatype == "Float64LE" || datatype == "Float64BE"))
    fail(path, "datatype \"" + datatype + "\"; tracks are Float32LE, Float32BE, Float64LE or Float64BE");
  const bool bigEndian = datatype.ends_with("BE");
  if (file.size() < 3 || file.compare(0, 2, ". ") != 0)
    fail(path, "the header's \"file\" is \"" + file + "\"; only \". OFFSET\" (data in this file) is read");
  const std::optional<long long> offset = util::parseInteger(trimmed(file.substr(2)));
  if (!offset || *offset < 0) fail(path, "the header's data offset \"" + file.substr(2) + "\" is not a whole number");
  if (std::uint64_t(*offset) < headerEnd) fail(path, "the data offset " + std::to_string(*offset) + " lies inside the header");
  if (std::uint64_t(*offset) > size)
    fail(path, "the data offset " + std::to_string(*offset) + " lies beyond the file's " + std::to_string(size) + " bytes");
  const std::size_t value = f64 ? 8 : 4, triplet = 3 * value;
  const std::uint64_t bytes = size - std::uint64_t(*offset);
  if (bytes % triplet)
    fail(path, std::to_string(bytes) + " bytes of data, not a whole number of " + std::to_string(triplet) +
                   "-byte points: truncated");
  const std::uint64_t triplets = bytes / triplet;
  if (triplets == 0) fail(path, "no data after the header: truncated (not even the end marker)");
  // Our copy: at most 12 bytes a point, with its streamline's start.
  const std::uint64_t need = 20 * triplets + (16 << 20);
  if (memoryBudget && need > memoryBudget)
    fail(path, "reading would need about " + std::to_string(need >> 20) + " MiB, more than the " +
                   std::to_string(memoryBudget >> 20) + " MiB this load may use");
  if (promise) promise(bytes, need);
  if (std::fseek(f.get(), long(*offset), SEEK_SET) != 0) fail(path, "cannot seek to the data");

  TractData out;
  out.path = path;
  TractBuilder build(out, "readTracts: " + path);
  std::vector<unsigned char> chunk(triplet * 8192);
  bool endMarker = false;
  for (std::uint64_t done = 0; done < triplets;) {
    const std::size_t n = std::size_t(std::min<std::uint64_t>(triplets - done, 8192));
    if (std::fread(chunk.data(), triplet, n, f.get()) != n) fail(path, "the data could not be read: truncated");
    for (std::size_t k = 0; k < n; ++k, ++done) {
      double v[3];
      for (int c = 0; c < 3; ++c) {
        const unsigned char* p = &chunk[k * triplet + std::size_t(c) * value];
        v[c] = f64 ? fromBytes<double>(p, bigEndian) : double(fromBytes<float>(p, bigEndian));
      }
      if (std::isnan(v[0]) && std::isnan(v[1]) && std::isnan(v[2])) {
        build.end(false);  // nibabel skips empty streamlines, and so do we
      } else if (std::isinf(v[0]) && std::isinf(v[1]) && std::isinf(v[2])) {
        if (done + 1 != triplets)
          fail(path, std::to_string(triplets - done - 1) + (triplets - done == 2 ? " point" : " points") +
                         " after the end marker (inf inf inf)");
        endMarker = true;
      } else {
        build.point(v[0], v[1], v[2]);
      }
    }
  }
  if (!endMarker) fail(path, "no end marker (inf inf inf) after the last point: truncated");
  if (build.open()) fail(path, "the last streamline has no NaN delimiter before the end marker: truncated");
  out.description = "MRtrix tracks (" + datatype + "), " + std::to_string(out.streamlineCount()) + " streamlines, " +
                    std::to_string(out.pointCount()) + " points";
  return out;
}

}  // namespace tg::io
