// MRtrix images, read by hand: no library in our stack reads them. A .mif
// holds its header and data; a .mih is a header naming a data file. The
// header is text ("mrtrix image", then "key: value" lines, then "END", which a
// .mih may leave out); every value that sizes or places the data is checked,
// and the data file's size against it, before anything is allocated from it.
// Data is then streamed in fixed-size chunks, in file order, into the
// VolumeSink.
// Choices where MRtrix is looser: dim, vox, layout, datatype and scaling may
// not repeat; data split over several files, Bit and complex types are
// refused; a transform whose 3x3 is not orthonormal is replaced by its polar
// rotation, with a warning (MRtrix keeps scaling in vox, never there).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/core/mif_datatype.h"
#include "io/core/raw_samples.h"
#include "io/core/readers.h"
#include "io/core/selection.h"
#include "io/core/volume_sink.h"
#include "util/huge_pages.h"
#include "util/strict_number.h"
#include "util/unique_fd.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readMif: " + path + ": " + what);
}

// Real headers are a few KB; a long dw_scheme or command_history reaches
// ~100 KB. The bounds stop a hostile header from costing memory or time.
constexpr std::size_t kMaxHeaderBytes = 16 << 20;
constexpr std::size_t kMaxLineBytes = 1 << 20;
constexpr std::size_t kReadBytes = 1 << 16;
constexpr std::size_t kChunkBytes = 1 << 22;
constexpr int kMaxAxes = 16;
// Transforms are written as text; below this, |RᵀR - I| is rounding.
constexpr double kOrthoTolerance = 1e-4;

using Fd = util::UniqueFd;

// O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused next.
Fd openRegular(const std::string& path, const std::string& file, const char* role, std::uint64_t& size) {
  Fd fd(::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (fd.get() < 0) fail(path, std::string("cannot open ") + role + " " + file + ": " + std::strerror(errno));
  struct stat st {};
  if (fstat(fd.get(), &st) != 0 || !S_ISREG(st.st_mode))
    fail(path, std::string(role) + " " + file + " is not a regular file");
  size = std::uint64_t(st.st_size);
  return fd;
}

// Exactly n bytes at `offset`; fewer means the file shrank since it was checked.
void readAt(const std::string& path, int fd, char* dst, std::size_t n, std::uint64_t offset) {
  while (n > 0) {
    const ssize_t got = ::pread(fd, dst, n, off_t(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) fail(path, "data is truncated: reading stopped at byte " + std::to_string(offset));
    dst += got;
    n -= std::size_t(got);
    offset += std::uint64_t(got);
  }
}

std::string_view trim(std::string_view s) {
  const auto ws = " \t\r";
  const auto b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(ws) - b + 1);
}

std::string lower(std::string_view s) {
  std::string l(s);
  std::transform(l.begin(), l.end(), l.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return l;
}

// "a, b,c" -> {"a", "b", "c"}; an empty item is an error.
std::vector<std::string_view> splitList(const std::string& path, const std::string& key, std::string_view v) {
  std::vector<std::string_view> items;
  for (std::size_t start = 0;;) {
    const std::size_t comma = v.find(',', start);
    const std::string_view item = trim(v.substr(start, comma == std::string_view::npos ? comma : comma - start));
    if (item.empty()) fail(path, key + ": empty item in \"" + std::string(v) + "\"");
    items.push_back(item);
    if (comma == std::string_view::npos) return items;
    start = comma + 1;
  }
}

std::uint64_t parseCount(const std::string& path, const std::string& key, std::string_view s) {
  const std::optional<long long> x = util::parseInteger(s);
  if (!x || *x < 0 || s[0] == '+' || s[0] == '-')
    fail(path, key + ": \"" + std::string(s) + "\" is not a non-negative integer");
  return std::uint64_t(*x);
}

double parseReal(const std::string& path, const std::string& key, std::string_view s) {
  const std::optional<double> x = util::parseNumber(s);
  if (!x) fail(path, key + ": \"" + std::string(s) + "\" is not a number");
  if (!std::isfinite(*x)) fail(path, key + ": " + std::string(s) + " is not finite");
  return *x;
}

struct Header {
  std::vector<std::uint64_t> dim;
  std::size_t voxCount = 0;
  double vox[3] = {1, 1, 1};
  std::vector<int> rank;  // layout: order of increasing stride, 0 fastest
  std::vector<bool> descending;
  std::string layoutText;
  MifDataType type;
  std::vector<std::array<double, 4>> transform;
  double offset = 0, scale = 1;
  bool scaled = false;
  std::string dataFile;  // as named; "." is the header's own file
  std::uint64_t dataOffset = 0;
  std::uint64_t headerEnd = 0;  // first byte after the END line
  std::uint64_t values = 0;     // product of dim
};

// A .mih is all header: MRtrix 3.0's mrconvert writes it without an END
// line, and MRtrix's parser stops at END or the end of the file. A .mif
// must say where its header ends, since its data follows.
bool headerMayEndAtEof(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  return name.size() > 4 && lower(std::string_view(name).substr(name.size() - 4)) == ".mih";
}

// Hands each "key: value" entry up to END, in order, to entry(key, value);
// none is kept, so 16 MiB of comments cost no more than their buffer. Keys
// are lower case and '#' starts a comment, as in MRtrix's own parser.
template <class Entry>
void readEntries(const std::string& path, int fd, std::uint64_t size, std::uint64_t& headerEnd, Entry&& entry) {
  static constexpr std::string_view kMagic = "mrtrix image";
  std::string buf;
  std::size_t lineStart = 0, lineNo = 0;
  for (;;) {
    const std::size_t nl = buf.find('\n', lineStart);
    if (nl == std::string::npos) {
      if (buf.size() - lineStart > kMaxLineBytes)
        fail(path, "header line " + std::to_string(lineNo + 1) + " is longer than 1 MiB");
      if (buf.size() >= kMaxHeaderBytes) fail(path, "no END line within the first 16 MiB");
      if (buf.size() >= size) {
        if (!headerMayEndAtEof(path)) fail(path, "header has no END line");
        headerEnd = size;
        return;
      }
      const std::size_t old = buf.size();
      const std::size_t n = std::size_t(std::min<std::uint64_t>(kReadBytes, size - old));
      buf.resize(old + n);
      readAt(path, fd, buf.data() + old, n, old);
      // Anything else is refused from its first bytes, not after 16 MiB.
      if (old == 0 && buf.compare(0, std::min(buf.size(), kMagic.size()), kMagic, 0, buf.size()) != 0)
        fail(path, "not an MRtrix image: the first line is not \"mrtrix image\"");
      if (buf.size() == size) buf.push_back('\n');  // the last line may lack its newline
      continue;
    }
    std::string_view line(buf.data() + lineStart, nl - lineStart);
    lineStart = nl + 1;
    ++lineNo;
    if (line.find('\0') != std::string_view::npos)
      fail(path, "header line " + std::to_string(lineNo) + " holds a NUL byte");
    if (lineNo == 1) {
      if (trim(line) != kMagic) fail(path, "not an MRtrix image: the first line is not \"mrtrix image\"");
      continue;
    }
    line = trim(line.substr(0, line.find('#')));
    if (line.empty()) continue;
    if (line == "END") {
      headerEnd = std::min<std::uint64_t>(lineStart, size);
      return;
    }
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos)
      fail(path, "header line " + std::to_string(lineNo) + " is not \"key: value\"");
    const std::string key = lower(trim(line.substr(0, colon)));
    if (key.empty()) fail(path, "header line " + std::to_string(lineNo) + " has no key");
    entry(key, std::string(trim(line.substr(colon + 1))));
  }
}

void parseLayout(const std::string& path, Header& h, const std::string& value) {
  h.layoutText = value;
  for (auto item : splitList(path, "layout", value)) {
    bool down = false;
    if (item[0] == '+' || item[0] == '-') {
      down = item[0] == '-';
      item.remove_prefix(1);
    }
    const std::uint64_t r = parseCount(path, "layout", item);
    if (r >= std::uint64_t(kMaxAxes)) fail(path, "layout: axis order " + std::string(item) + " is out of range");
    h.rank.push_back(int(r));
    h.descending.push_back(down);
  }
}

void parseEntry(const std::string& path, Header& h, const std::string& key, const std::string& value,
                std::vector<std::string>& seen, int& files) {
  // Keys that may repeat: transform (its rows), file (refused below when
  // more than one), and the free text that MRtrix itself repeats (comments,
  // command_history, dw_scheme...), which is not used here.
  if (key == "dim" || key == "vox" || key == "layout" || key == "datatype" || key == "scaling") {
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) fail(path, "key \"" + key + "\" appears twice");
    seen.push_back(key);
  }
  if (key == "dim") {
    for (const auto item : splitList(path, key, value)) {
      const std::uint64_t d = parseCount(path, key, item);
      if (d < 1 || d > std::uint64_t(INT32_MAX)) fail(path, "dim: size " + std::string(item) + " is not 1..2^31-1");
      if (h.dim.size() == std::size_t(kMaxAxes)) fail(path, "dim: more than 16 axes");
      h.dim.push_back(d);
    }
  } else if (key == "vox") {
    const auto items = splitList(path, key, value);
    if (items.size() < 3) fail(path, "vox: fewer than three voxel sizes");
    // Sizes of other axes (the tensor axis's is often NaN) are not used.
    for (std::size_t k = 0; k < 3; ++k) {
      h.vox[k] = parseReal(path, key, items[k]);
      if (!(h.vox[k] > 0)) fail(path, "vox: voxel size " + std::string(items[k]) + " is not positive");
    }
    h.voxCount = items.size();
  } else if (key == "layout") {
    parseLayout(path, h, value);
  } else if (key == "datatype") {
    h.type = parseMifDataType(path, value);
  } else if (key == "transform") {
    const auto items = splitList(path, key, value);
    if (items.size() != 4) fail(path, "transform: a row holds " + std::to_string(items.size()) + " numbers, not 4");
    if (h.transform.size() == 3) fail(path, "transform: more than three rows");
    std::array<double, 4> row{};
    for (std::size_t k = 0; k < 4; ++k) row[k] = parseReal(path, key, items[k]);
    h.transform.push_back(row);
  } else if (key == "scaling") {
    const auto items = splitList(path, key, value);
    if (items.size() != 2) fail(path, "scaling: expected \"offset,scale\"");
    h.offset = parseReal(path, key, items[0]);
    h.scale = parseReal(path, key, items[1]);
    h.scaled = !(h.offset == 0 && h.scale == 1);
  } else if (key == "file") {
    if (++files > 1) fail(path, "data split over several files is not supported");
    const std::string_view v = value;
    const std::size_t sp = v.find_first_of(" \t");
    h.dataFile = std::string(v.substr(0, sp));
    if (h.dataFile.empty()) fail(path, "file: no file named");
    if (sp != std::string_view::npos) h.dataOffset = parseCount(path, "file offset", trim(v.substr(sp)));
  }
}

Header parseHeader(const std::string& path, int fd, std::uint64_t size) {
  Header h;
  std::vector<std::string> seen;
  int files = 0;
  readEntries(path, fd, size, h.headerEnd,
              [&](const std::string& key, const std::string& value) { parseEntry(path, h, key, value, seen, files); });
  for (const char* key : {"dim", "vox", "layout", "datatype"})
    if (std::find(seen.begin(), seen.end(), key) == seen.end()) fail(path, std::string("no ") + key + " in the header");
  if (files == 0) fail(path, "no file in the header");
  const std::size_t n = h.dim.size();
  if (h.voxCount != n || h.rank.size() != n)
    fail(path, "dim, vox and layout give " + std::to_string(n) + ", " + std::to_string(h.voxCount) + " and " +
                   std::to_string(h.rank.size()) + " axes");
  // The layout orders the axes by stride: a permutation of 0..n-1.
  std::vector<bool> used(n, false);
  for (const int r : h.rank) {
    if (std::size_t(r) >= n || used[std::size_t(r)])
      fail(path, "layout " + h.layoutText + " is not an order of the " + std::to_string(n) + " axes");
    used[std::size_t(r)] = true;
  }
  h.values = 1;
  for (const std::uint64_t d : h.dim)
    if (__builtin_mul_overflow(h.values, d, &h.values)) fail(path, "dim: the image size overflows");
  if (!h.transform.empty() && h.transform.size() != 3) fail(path, "transform: three rows needed");
  return h;
}

// A header and its data file, checked against each other.
struct Image {
  Header h;
  Fd data;
  std::string dataPath;
};

// The data file a header names, relative to the header's folder.
std::string dataPathOf(const std::string& path, const Header& h) {
  if (h.dataFile == ".") return path;
  const std::filesystem::path named(h.dataFile);
  return named.is_absolute() ? named.string() : (std::filesystem::path(path).parent_path() / named).string();
}

// `shape` checks the dimensions the caller needs; it runs before the data
// file is opened, and the data's size is checked before anything is read.
template <class Shape>
Image openImage(const std::string& path, Shape&& shape) {
  Image im;
  std::uint64_t size = 0;
  Fd header = openRegular(path, path, "header", size);
  im.h = parseHeader(path, header.get(), size);
  Header& h = im.h;
  shape(h);
  if (h.dataFile == ".") {
    im.dataPath = path;
    im.data = std::move(header);
    if (h.dataOffset < h.headerEnd)
      fail(path, "data offset " + std::to_string(h.dataOffset) + " lies inside the header (" +
                     std::to_string(h.headerEnd) + " bytes)");
  } else {
    im.dataPath = dataPathOf(path, h);
    im.data = openRegular(path, im.dataPath, "data file", size);
  }
  std::uint64_t bytes = 0;
  if (__builtin_mul_overflow(h.values, std::uint64_t(rawTypeBytes(h.type.type)), &bytes))
    fail(path, "dim: the image size overflows");
  if (h.dataOffset > size)
    fail(path, "data offset " + std::to_string(h.dataOffset) + " is beyond the end of " + im.dataPath + " (" +
                   std::to_string(size) + " bytes)");
  if (bytes > size - h.dataOffset)
    fail(path, "data is truncated: the header describes " + std::to_string(bytes) + " bytes at offset " +
                   std::to_string(h.dataOffset) + ", " + im.dataPath + " has " + std::to_string(size - h.dataOffset));
  return im;
}

std::uint64_t spatialVoxels(const std::string& path, const Header& h) {
  const std::uint64_t v = h.dim[0] * h.dim[1] * h.dim[2];  // each < 2^31: no overflow
  if (v > kMaxInputs) fail(path, "more than 2^32-256 voxels");
  return v;
}

std::string dimsText(const Header& h) {
  std::string s;
  for (const std::uint64_t d : h.dim) {
    if (!s.empty()) s += 'x';
    s += std::to_string(d);
  }
  return s;
}

// Streams every value of the image in file order, `record` at a time (a
// record never straddles two calls), scaled, into consume(values, n).
template <class Consume>
void streamValues(const std::string& path, const Image& im, std::size_t record, Consume&& consume) {
  const Header& h = im.h;
  const std::size_t tsize = rawTypeBytes(h.type.type);
  // h.values is a whole number of records.
  const std::size_t chunk = std::size_t(
      std::min<std::uint64_t>(std::max<std::size_t>(1, kChunkBytes / (tsize * record)) * record, h.values));
  std::vector<char> raw(chunk * tsize);
  std::vector<double> vals(chunk);
  for (std::uint64_t done = 0; done < h.values;) {
    const std::size_t want = std::size_t(std::min<std::uint64_t>(chunk, h.values - done));
    readAt(path, im.data.get(), raw.data(), want * tsize, h.dataOffset + done * tsize);
    rawToDoubles(h.type.type, h.type.swap, raw.data(), want, vals.data());
    if (h.scaled)
      for (std::size_t i = 0; i < want; ++i) vals[i] = h.offset + h.scale * vals[i];
    consume(static_cast<const double*>(vals.data()), want);
    done += want;
  }
}

// Where each value in file order belongs, for any layout: its voxel (index
// i fastest) and component. Axes are stepped in stride order; a descending
// axis starts at its last index.
class Walk {
 public:
  explicit Walk(const Header& h) : n_(int(h.dim.size())) {
    const std::int64_t voxelStride[3] = {1, std::int64_t(h.dim[0]), std::int64_t(h.dim[0] * h.dim[1])};
    for (int a = 0; a < n_; ++a) {
      const int k = h.rank[std::size_t(a)];
      const std::int64_t sign = h.descending[std::size_t(a)] ? -1 : 1;
      dim_[k] = std::int64_t(h.dim[std::size_t(a)]);
      dVoxel_[k] = a < 3 ? sign * voxelStride[a] : 0;
      dComp_[k] = a == 3 ? sign : 0;
      if (sign < 0) {
        voxel_ -= dVoxel_[k] * (dim_[k] - 1);
        comp_ -= dComp_[k] * (dim_[k] - 1);
      }
    }
  }
  std::uint64_t voxel() const { return std::uint64_t(voxel_); }
  std::size_t comp() const { return std::size_t(comp_); }
  void next() {
    for (int k = 0; k < n_; ++k) {
      if (++pos_[k] < dim_[k]) {
        voxel_ += dVoxel_[k];
        comp_ += dComp_[k];
        return;
      }
      pos_[k] = 0;
      voxel_ -= dVoxel_[k] * (dim_[k] - 1);
      comp_ -= dComp_[k] * (dim_[k] - 1);
    }
  }

 private:
  int n_;
  std::int64_t dim_[4] = {1, 1, 1, 1}, pos_[4] = {0, 0, 0, 0};
  std::int64_t dVoxel_[4] = {0, 0, 0, 0}, dComp_[4] = {0, 0, 0, 0};
  std::int64_t voxel_ = 0, comp_ = 0;
};

// True when file order is voxel by voxel, i fastest, components in order:
// the sink then takes the values as they come.
bool fileOrderIsIndexOrder(const Header& h) {
  if (std::find(h.descending.begin(), h.descending.end(), true) != h.descending.end()) return false;
  return h.dim.size() == 4 ? h.rank == std::vector<int>{1, 2, 3, 0} : h.rank == std::vector<int>{0, 1, 2};
}

// Index -> WC: world = R (ijk .* vox) + t, in MRtrix's scanner space (RAS).
VolumeGeometry geometry(const std::string& path, const Header& h, TensorField& f) {
  VolumeGeometry g;
  for (std::size_t k = 0; k < 3; ++k) g.dims[k] = int(h.dim[k]);
  std::array<double, 9> r{1, 0, 0, 0, 1, 0, 0, 0, 1};
  if (h.transform.empty()) {
    f.warnings.push_back("no transform; placed by vox alone");
  } else {
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t c = 0; c < 3; ++c) r[3 * i + c] = h.transform[i][c];
      g.originWC[i] = h.transform[i][3];
    }
    double norms = 1, err = 0;
    for (std::size_t c = 0; c < 3; ++c) norms *= std::hypot(r[c], r[3 + c], r[6 + c]);
    if (!(std::abs(determinant3(r.data())) > 1e-6 * norms)) fail(path, "transform: the rotation is singular");
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t b = 0; b < 3; ++b)
        err = std::max(err, std::abs(r[a] * r[b] + r[3 + a] * r[3 + b] + r[6 + a] * r[6 + b] - (a == b)));
    // MRtrix writes a rotation, scaling being in vox; anything else is
    // taken for its nearest rotation, said aloud.
    if (err > kOrthoTolerance) {
      r = orthogonalPart(r.data());
      f.warnings.push_back("transform: the rotation is not orthonormal (max |RᵀR - I| = " + std::to_string(err) +
                           "); its orthogonal part is used");
    }
  }
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t c = 0; c < 3; ++c) g.axesWC[3 * i + c] = r[3 * i + c] * h.vox[c];
  return g;
}

}  // namespace

TensorField readMif(const std::string& path, const ReadOptions& opt) {
  if (const std::string o = inapplicableOption(InputFormat::Mif, opt); !o.empty())
    fail(path, o + " does not apply: MRtrix images hold xx yy zz xy xz yz in scanner space");
  const Image im = openImage(path, [&](const Header& h) {
    if (h.dim.size() != 4 || h.dim[3] != 6)
      fail(path, "dimensions " + dimsText(h) + " hold no tensor; expected 4 axes, the last of 6 values");
    spatialVoxels(path, h);
  });
  const Header& h = im.h;
  TensorField f;
  f.path = path;
  VolumeGeometry g = geometry(path, h, f);
  f.space = h.transform.empty() ? "voxel grid (no transform)" : "RAS (MRtrix scanner space)";
  f.layout = "mrtrix (xx yy zz xy xz yz)";
  f.frame = "world: MRtrix's scanner space, as dwi2tensor writes it; not rotated";
  f.description = "MRtrix image, " + dimsText(h) + ", " + h.type.name + ", layout " + h.layoutText +
                  (h.scaled ? ", scaled" : "") + (im.dataPath == path ? "" : ", data in " + im.dataPath);
  ComponentLayout cl;
  cl.sym = {0, 3, 4, 1, 5, 2};
  const std::uint64_t voxels = spatialVoxels(path, h);
  const GridPlacement placed = placementOf(g);
  const Selector sel(opt.selection, path, g.dims, &placed);
  promiseData("readMif", path, opt, 6 * voxels * std::uint64_t(rawTypeBytes(h.type.type)), sel.keptBound(voxels));
  if (fileOrderIsIndexOrder(h)) {
    // Voxel by voxel, as a raw NRRD: the guard's parent reads the values
    // (io/core/raw_samples.h), where no mask needs reading beside them.
    RawSamples raw{util::UniqueFd{}, h.dataOffset, h.type.type, h.type.swap, g, cl, h.offset, h.scale};
    if (opt.deferRaw && opt.selection.maskPath.empty()) {
      raw.dataFd = util::UniqueFd(::fcntl(im.data.get(), F_DUPFD_CLOEXEC, 0));
      if (!raw.dataFd) fail(path, std::string("cannot hand the data file over: ") + std::strerror(errno));
      *opt.deferRaw = std::move(raw);
      return f;
    }
    readRawSamples("readMif", path, raw, opt, f, im.data.get(), &sel);
    return f;
  }
  VolumeSink sink(f, g, cl, sel, 0.0);
  // Any other layout: the kept voxels' components are gathered first,
  // then handed to the sink in index order, as NIfTI's volumes are.
  constexpr std::uint32_t kDropped = UINT32_MAX;
  std::vector<std::uint32_t> kept, slotOf;  // empty: every voxel is kept, slot = index
  if (!sel.selectsAll()) {
    slotOf.assign(std::size_t(voxels), kDropped);
    for (std::uint64_t v = 0; v < voxels; ++v)
      if (sink.accept(v)) {
        slotOf[std::size_t(v)] = std::uint32_t(kept.size());
        kept.push_back(std::uint32_t(v));
      }
  }
  const std::size_t keptCount = sel.selectsAll() ? std::size_t(voxels) : kept.size();
  // On huge pages: faulting 4 KiB pages in was most of this path's cost
  // (bench_load, loadMif at 256^3: 100k faults a load).
  FloatGather comps;
  comps.reserve(6 * keptCount);
  comps.resize(6 * keptCount);
  Walk walk(h);
  streamValues(path, im, 6, [&](const double* v, std::size_t m) {
    for (std::size_t i = 0; i < m; ++i, walk.next()) {
      const std::size_t slot = slotOf.empty() ? std::size_t(walk.voxel()) : slotOf[std::size_t(walk.voxel())];
      if (slot != kDropped) comps.set(6 * slot + walk.comp(), v[i]);
    }
  });
  f.reserve(keptCount);
  double v6[6];
  for (std::size_t s = 0; s < keptCount; ++s) {
    for (std::size_t c = 0; c < 6; ++c) v6[c] = comps.get(6 * s + c);
    // Every voxel in index order is push()'s case, placed incrementally.
    if (kept.empty()) sink.push(v6);
    else sink.pushAccepted(kept[s], v6);
  }
  sink.finish();
  return f;
}

std::string mifDataFile(const std::string& path) {
  std::uint64_t size = 0;
  const Fd header = openRegular(path, path, "header", size);
  return dataPathOf(path, parseHeader(path, header.get(), size));
}

ScalarVolume readMifScalar(const std::string& path, const int dims[3]) {
  const Image im = openImage(path, [&](const Header& h) {
    if (h.dim.size() != 3) fail(path, "a mask or underlay must have 3 axes, this has " + std::to_string(h.dim.size()));
    spatialVoxels(path, h);
    const int got[3] = {int(h.dim[0]), int(h.dim[1]), int(h.dim[2])};
    if (const std::string m = maskGridMismatch(got, dims); !m.empty()) fail(path, m);
  });
  ScalarVolume s;
  for (std::size_t k = 0; k < 3; ++k) s.dims[k] = int(im.h.dim[k]);
  TensorField unused;
  if (!im.h.transform.empty()) s.placement = placementOf(geometry(path, im.h, unused));
  s.values.resize(std::size_t(im.h.values));
  Walk walk(im.h);
  streamValues(path, im, 1, [&](const double* v, std::size_t m) {
    for (std::size_t i = 0; i < m; ++i, walk.next()) s.values[std::size_t(walk.voxel())] = float(v[i]);
  });
  return s;
}

}  // namespace tg::io
