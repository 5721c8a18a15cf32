// NRRD through Teem: Teem parses the header (skipData), we check it against
// the file before anything is allocated from it, then decode the data in
// fixed-size chunks straight into the VolumeSink, so that no copy of the
// file's data is ever held.
#include <bzlib.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <teem/air.h>
#include <teem/nrrd.h>

#include <algorithm>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <cctype>
#include <optional>
#include <string_view>
#include <filesystem>
#include <functional>
#include <memory>

#include "io/core/format_impl.h"
#include "io/core/gzip_errors.h"
#include "io/modules/teem/nrrd_numbers.h"
#include "io/core/raw_samples.h"
#include "io/core/readers.h"
#include "io/modules/teem/teem_util.h"
#include "io/core/volume_sink.h"
#include "util/strict_number.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readNrrd: " + path + ": " + what);
}

// zlib's deflate cannot do better than ~1032:1, so a gzip stream promising
// more decoded bytes than that is corrupt. bzip2's run-length stage allows far
// more; it is bounded by the stream itself as it is decoded in chunks.
constexpr std::uint64_t kMaxGzipRatio = 1032;
constexpr std::size_t kChunkBytes = 1 << 22;

struct Header {
  Nrrd* nrrd = nrrdNew();
  NrrdIoState* nio = nrrdIoStateNew();
  ~Header() {
    if (nio->dataFile) std::fclose(nio->dataFile);
    nio->dataFile = nullptr;
    nrrdIoStateNix(nio);
    nrrdNuke(nrrd);
  }
};

// The header only, with the data file left open at the first data byte.
std::unique_ptr<Header> readHeader(const std::string& path) {
  {
    std::unique_ptr<FILE, int (*)(FILE*)> in(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!in) fail(path, "cannot open file");
    impl::checkNrrdHeaderText("readNrrd", path, in.get());
    checkNrrdHeaderNumbers("readNrrd", path, in.get());
  }
  // Teem opens its data files in nrrdLoad even with skipData, and the open of
  // a FIFO blocks; stat tells without opening.
  std::vector<std::string> dataFiles;
  try {
    dataFiles = impl::nrrdDataFiles(path);
  } catch (const impl::NrrdDataFilesRefused&) {
    throw;
  } catch (const InputError&) {
    // A header it cannot parse: nrrdLoad below reports the same fault as ours.
  }
  if (dataFiles.size() > 1) fail(path, "multiple detached data files are not supported");
  // Said here, not by Teem: its message quotes the data file's whole path
  // into biff's 1 KiB stack buffer, which a header in a deep directory
  // overflowed (an abort, reported as a crash of the reader).
  for (const std::string& data : dataFiles) {
    struct stat st {};
    if (stat(data.c_str(), &st) != 0 || access(data.c_str(), R_OK) != 0)
      fail(path, "data file " + data + " cannot be read: " + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) fail(path, "data file " + data + " is not a regular file");
  }
  auto h = std::make_unique<Header>();
  h->nio->skipData = AIR_TRUE;
  h->nio->keepNrrdDataFileOpen = AIR_TRUE;
  // nrrdLoad's steps, with the header opened here: its own message on any
  // failure quotes the header's whole path into biff's 1 KiB stack buffer,
  // which a header in a deep directory overflowed (an abort). Teem finds
  // detached data through nio->path, the header's directory, as nrrdLoad
  // sets it.
  const std::filesystem::path where(path);
  h->nio->path = airStrdup(where.has_parent_path() ? where.parent_path().c_str() : ".");
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) fail(path, std::string("cannot open file: ") + std::strerror(errno));
  if (nrrdRead(h->nrrd, file, h->nio)) {
    // On failure Teem may already have closed the file it left in dataFile
    // (found by fuzz_nrrd: a double fclose); it is not ours to close then.
    h->nio->dataFile = nullptr;
    std::fclose(file);
    fail(path, teemNrrdError());
  }
  // An attached header's file is its data file, kept open; a detached
  // header's file is done with.
  if (h->nio->dataFile != file) std::fclose(file);
  if (h->nio->format != nrrdFormatNRRD) fail(path, "not a NRRD file");
  if (!h->nio->dataFile) fail(path, "multiple detached data files are not supported");
  // A device or pipe never ends or cannot be sized; only a file can hold data.
  struct stat st {};
  if (fstat(fileno(h->nio->dataFile), &st) != 0 || !S_ISREG(st.st_mode))
    fail(path, "the data file is not a regular file");
  if (h->nrrd->type == nrrdTypeBlock) fail(path, "type block holds no numbers");
  return h;
}

// Bytes of the data file from where the data begins.
std::uint64_t bytesAfterHeader(const Header& h) {
  struct stat st {};
  fstat(fileno(h.nio->dataFile), &st);
  const long pos = std::ftell(h.nio->dataFile);
  return pos >= 0 && st.st_size >= pos ? std::uint64_t(st.st_size - pos) : 0;
}

// A compressed stream's reader: the next `want` bytes into `dst`, fewer only
// where the stream ends. Throws on corrupt data.
using ByteReader = std::function<std::size_t(char* dst, std::size_t want)>;

struct GzCloser {
  void operator()(gzFile gz) const { gzclose(gz); }
};
struct BzStream {
  BZFILE* bz = nullptr;
  int err = BZ_OK;  // libbz2's status of the last call
  ~BzStream() {
    int closeErr;
    if (bz) BZ2_bzReadClose(&closeErr, bz);
  }
};

// The data must fit in what follows the header: raw bytes as they are, text
// at one byte a value at least (two a byte in hex), gzip within deflate's
// ratio. Checked before anything is sized from the header.
void checkEncodedSize(const std::string& path, const Header& h, std::uint64_t count) {
  const NrrdEncoding* enc = h.nio->encoding;
  const std::uint64_t bytes = count * nrrdTypeSize[h.nrrd->type];
  const std::uint64_t avail = bytesAfterHeader(h);
  const std::uint64_t need = enc == nrrdEncodingHex ? 2 * bytes : enc == nrrdEncodingAscii ? count
                             : enc == nrrdEncodingRaw ? bytes : 0;
  if (need > avail)
    fail(path, "data is truncated: the header describes " + std::to_string(bytes) + " bytes, the data ends after " +
                   std::to_string(enc == nrrdEncodingRaw ? avail : 0));
  if (enc == nrrdEncodingGzip && bytes > avail * kMaxGzipRatio)
    fail(path, "header describes more data than the gzip stream can hold");
}

RawType rawTypeOf(int type) {
  switch (type) {
    case nrrdTypeChar: return RawType::I8;
    case nrrdTypeUChar: return RawType::U8;
    case nrrdTypeShort: return RawType::I16;
    case nrrdTypeUShort: return RawType::U16;
    case nrrdTypeInt: return RawType::I32;
    case nrrdTypeUInt: return RawType::U32;
    case nrrdTypeLLong: return RawType::I64;
    case nrrdTypeULLong: return RawType::U64;
    case nrrdTypeFloat: return RawType::F32;
    case nrrdTypeDouble: return RawType::F64;
    default: throw std::logic_error("rawTypeOf: NRRD type " + std::to_string(type) + " has no raw form");
  }
}

// One whitespace-separated word of ascii data, as Teem's decoder splits
// them (fscanf's %s), into `word`; false at the end of the file.
bool nextWord(FILE* file, std::string& word) {
  word.clear();
  int c;
  while ((c = std::getc(file)) != EOF && std::isspace(c)) {}
  for (; c != EOF && !std::isspace(c); c = std::getc(file)) {
    // Teem reads each word into a fixed 1 KiB buffer.
    if (word.size() == 512) return true;
    word.push_back(char(c));
  }
  return !word.empty();
}

// Ascii data, read here rather than by Teem: its decoder takes a word's
// longest numeric prefix (sscanf), so "3,5" read as 3 and "1.5abc" as 1.5,
// and it parses into the declared type, so that 300 became 44 in a uchar
// file. Each word must be a whole number (util/strict_number.h), in the
// declared type's range. Commas between values, which Teem passes over, are
// allowed: an isolated "," and commas before or after a value.
template <class Consume>
void decodeAscii(const std::string& path, FILE* file, int declared, std::uint64_t count, std::size_t chunkValues,
                 std::vector<double>& vals, Consume& consume) {
  const double lo = nrrdTypeMin[declared], hi = nrrdTypeMax[declared];
  const bool integral = nrrdTypeIsIntegral[declared];
  std::string word;
  std::uint64_t done = 0;
  std::size_t filled = 0;
  while (done + filled < count) {
    if (!nextWord(file, word))
      fail(path, "data is truncated: the ascii data ends after " + std::to_string(done + filled) + " of " +
                     std::to_string(count) + " values");
    if (word.size() == 512) fail(path, "ascii data holds a word longer than 511 characters");
    const std::size_t first = word.find_first_not_of(',');
    if (first == std::string::npos) continue;
    const std::string_view text = std::string_view(word).substr(first, word.find_last_not_of(',') + 1 - first);
    const std::string where = " (value " + std::to_string(done + filled) + ")";
    const std::optional<double> v = util::parseNumber(text);
    if (!v) fail(path, "ascii value \"" + std::string(text) + "\"" + where + " is not a number");
    if (integral && !(*v >= lo && *v <= hi && *v == std::floor(*v)))
      fail(path, "ascii value " + std::string(text) + where + " is not a " + airEnumStr(nrrdType, declared));
    if (declared == nrrdTypeFloat && std::isfinite(*v) && std::abs(*v) > FLT_MAX)
      fail(path, "ascii value " + std::string(text) + where + " is beyond the float range");
    vals[filled++] = *v;
    if (filled == chunkValues || done + filled == count) {
      consume(vals.data(), filled);
      done += filled;
      filled = 0;
    }
  }
}

// Streams `count` values, `record` at a time (a voxel's values never straddle
// two calls), into `consume(const double* values, size_t n)`.
template <class Consume>
void decode(const std::string& path, Header& h, std::uint64_t count, std::size_t record, Consume&& consume) {
  Nrrd* n = h.nrrd;
  NrrdIoState* nio = h.nio;
  const std::size_t tsize = nrrdTypeSize[n->type];
  const std::uint64_t bytes = count * tsize;
  FILE* file = nio->dataFile;
  const long pos = std::ftell(file);
  // Whole records, at most 4 MiB, and no more than the data: a fresh reader
  // process pays a page fault for every page of these buffers.
  const std::uint64_t records = std::min<std::uint64_t>(std::max<std::size_t>(1, kChunkBytes / (tsize * record)),
                                                         (count + record - 1) / record);
  const std::size_t chunkValues = std::size_t(records) * record;
  std::vector<char> buf(chunkValues * tsize);
  std::vector<double> vals(chunkValues);
  auto truncated = [&](std::uint64_t done) {
    fail(path, "data is truncated: the header describes " + std::to_string(bytes) + " bytes, the data ends after " +
                   std::to_string(done));
  };

  checkEncodedSize(path, h, count);
  if (nio->encoding == nrrdEncodingAscii) {
    decodeAscii(path, file, n->type, count, chunkValues, vals, consume);
    return;
  }
  if (nio->encoding == nrrdEncodingHex) {
    // Teem's hex decoder gives the bytes in file order; its nrrdRead swaps
    // them afterwards where the endian field differs (hex is an encoding
    // whose endianness matters), as the raw path does here.
    const bool swap = tsize > 1 && nio->endian != airMyEndian();
    for (std::uint64_t done = 0; done < count;) {
      const std::size_t want = std::size_t(std::min<std::uint64_t>(chunkValues, count - done));
      if (nio->encoding->read(file, buf.data(), want, n, nio)) fail(path, teemNrrdError());
      rawToDoubles(rawTypeOf(n->type), swap, buf.data(), want, vals.data());
      consume(vals.data(), want);
      done += want;
    }
    return;
  }

  // Binary encodings: one reader per encoding, one chunk loop for all.
  ByteReader read;
  std::unique_ptr<gzFile_s, GzCloser> gz;
  BzStream bz;
  if (nio->encoding == nrrdEncodingRaw) {
    read = [&](char* dst, std::size_t want) { return std::fread(dst, 1, want, file); };
  } else if (nio->encoding == nrrdEncodingGzip) {
    // zlib reads the descriptor from its own offset, so hand it a duplicate
    // positioned where stdio's buffered position says the data begins.
    const int fd = dup(fileno(file));
    if (fd < 0 || lseek(fd, pos, SEEK_SET) != pos) fail(path, "cannot reopen the data file");
    gz.reset(gzdopen(fd, "rb"));
    if (!gz) {
      close(fd);
      fail(path, "cannot open the gzip stream");
    }
    gzbuffer(gz.get(), 1 << 18);
    // zlib passes non-gzip bytes through unchanged; the header said gzip.
    if (gzdirect(gz.get())) fail(path, "gzip data is corrupt: no gzip stream where the data begins");
    read = [&](char* dst, std::size_t want) {
      const int got = gzread(gz.get(), dst, unsigned(want));
      if (got < 0) fail(path, gzipReadError(gz.get()));
      return std::size_t(got);
    };
  } else if (nio->encoding == nrrdEncodingBzip2) {
    bz.bz = BZ2_bzReadOpen(&bz.err, file, 0, 0, nullptr, 0);
    if (bz.err != BZ_OK) fail(path, "cannot open the bzip2 stream");
    read = [&](char* dst, std::size_t want) {
      std::size_t got = 0;
      while (got < want && bz.err != BZ_STREAM_END) {  // bzip2 returns short reads mid-stream
        const int g = BZ2_bzRead(&bz.err, bz.bz, dst + got, int(want - got));
        if (bz.err != BZ_OK && bz.err != BZ_STREAM_END)
          fail(path, "bzip2 data is corrupt (libbz2 error " + std::to_string(bz.err) + ")");
        got += std::size_t(std::max(g, 0));
      }
      return got;
    };
  } else {
    fail(path, std::string("encoding ") + nio->encoding->name + " is not supported");
  }
  // Compressed encodings skip bytes inside the decompressed stream.
  for (long skip = nio->encoding->isCompression ? nio->byteSkip : 0; skip > 0;) {
    const std::size_t got = read(buf.data(), std::size_t(std::min<long>(skip, long(buf.size()))));
    if (got == 0) fail(path, "data ends inside the byte skip");
    skip -= long(got);
  }
  const bool swap = nio->encoding->endianMatters && tsize > 1 && nio->endian != airMyEndian();
  for (std::uint64_t done = 0; done < bytes;) {
    const std::size_t want = std::size_t(std::min<std::uint64_t>(buf.size(), bytes - done));
    const std::size_t got = read(buf.data(), want);
    if (got != want) truncated(done + got);
    const std::size_t m = want / tsize;
    rawToDoubles(rawTypeOf(n->type), swap, buf.data(), m, vals.data());
    consume(vals.data(), m);
    done += want;
  }
  // One read past the data reaches the end of a compressed stream, where
  // zlib and libbz2 check its CRC: a stream cut at its trailer, or with
  // corrupt data that still inflates, is refused rather than trusted.
  if (nio->encoding == nrrdEncodingGzip || nio->encoding == nrrdEncodingBzip2) {
    char extra;
    read(&extra, 1);
    if (nio->encoding == nrrdEncodingGzip)
      if (const std::string problem = gzipTrailerError(gz.get()); !problem.empty()) fail(path, problem);
  }
}

// The three spatial axes' sizes from axis `first` on (1 beyond the last axis).
std::uint64_t gridDims(const std::string& path, const Nrrd* n, unsigned first, int dims[3]) {
  std::uint64_t voxels = 1;
  for (unsigned k = 0; k < 3; ++k) {
    const std::size_t size = first + k < n->dim ? n->axis[first + k].size : 1;
    if (size > std::size_t(INT32_MAX)) fail(path, "axis " + std::to_string(first + k) + " is too long");
    dims[k] = int(size);
    voxels *= size;
  }
  if (voxels > kMaxInputs) fail(path, "more than 2^32-256 voxels");
  return voxels;
}

// Where an old header (no space) puts samples 0 and 1 of axis `ax`, as
// Teem's nrrdAxisInfoPos does: from the axis min and max, cell-centred
// unless "centers" says node (Teem's default centring), so that sample i of
// n cells lies at min + (i + 0.5)(max - min)/n, of n nodes at min + i(max -
// min)/(n - 1). One sample of a cell lies midway; one node must have min ==
// max. Without a max the spacing (else 1) steps from the min, with the
// same half step for cells; without a min, back from the max.
void axisPlacement(const std::string& path, const Nrrd* n, unsigned ax, double& p0, double& step) {
  const NrrdAxisInfo& a = n->axis[ax];
  const bool cell = (a.center == nrrdCenterUnknown ? nrrdDefaultCenter : a.center) == nrrdCenterCell;
  const double size = double(a.size);
  p0 = 0;
  step = std::isfinite(a.spacing) ? a.spacing : 1.0;
  if (std::isfinite(a.min) && std::isfinite(a.max)) {
    if (cell || a.size > 1) {
      p0 = nrrdAxisInfoPos(n, ax, 0);
      step = nrrdAxisInfoPos(n, ax, 1) - p0;
    } else if (a.min == a.max) {
      p0 = a.min;
    } else {
      fail(path, "axis " + std::to_string(ax) + " holds one node-centred sample, but its axis min and max differ");
    }
  } else if (std::isfinite(a.min)) {
    p0 = a.min + (cell ? step / 2 : 0.0);
  } else if (std::isfinite(a.max)) {
    p0 = a.max - step * (cell ? size - 0.5 : size - 1);
  }
}

// Index -> WC from space directions, or for old headers from axis
// spacings or mins/maxs (Teem's nrrdAxisInfoPos honours the centering).
VolumeGeometry geometry(const std::string& path, const Nrrd* n, unsigned first, TensorField& f) {
  VolumeGeometry g;
  gridDims(path, n, first, g.dims);
  if (n->spaceDim == 3) {
    for (unsigned k = 0; k < 3 && first + k < n->dim; ++k) {
      const double* d = n->axis[first + k].spaceDirection;
      if (!(std::isfinite(d[0]) && std::isfinite(d[1]) && std::isfinite(d[2])))
        fail(path, "axis " + std::to_string(first + k) + " has no space direction");
      for (int r = 0; r < 3; ++r) g.axesWC[3 * r + k] = d[r];
    }
    for (int r = 0; r < 3; ++r) g.originWC[r] = std::isfinite(n->spaceOrigin[r]) ? n->spaceOrigin[r] : 0.0;
    if (!std::isfinite(n->spaceOrigin[0])) f.warnings.push_back("no space origin; using (0,0,0)");
  } else if (n->spaceDim == 0) {
    for (unsigned k = 0; k < 3 && first + k < n->dim; ++k)
      axisPlacement(path, n, first + k, g.originWC[k], g.axesWC[4 * k]);
  } else {
    fail(path, "space of dimension " + std::to_string(n->spaceDim) + " is not supported; tensors need 3");
  }
  return g;
}

// World space: RAS, with LPS and LAS turned into it (positions here; the
// tensors by the same signs, which `flip` returns); others as given, but for
// 3D-left-handed, whose x is negated as LAS's is: drawn in our right-handed
// world as it stands, every shape would be its mirror image.
void toRas(const Nrrd* n, VolumeGeometry& g, double flip[3]) {
  flip[0] = flip[1] = flip[2] = 1;
  if (n->space == nrrdSpaceLeftPosteriorSuperior || n->space == nrrdSpaceScannerXYZ) flip[0] = flip[1] = -1;
  if (n->space == nrrdSpaceLeftAnteriorSuperior || n->space == nrrdSpace3DLeftHanded) flip[0] = -1;
  for (int r = 0; r < 3; ++r) {
    g.originWC[r] *= flip[r];
    for (int c = 0; c < 3; ++c) g.axesWC[3 * r + c] *= flip[r];
  }
}

// The component layout of the tensor axis, from its kind or else its size.
ComponentLayout layoutOf(const std::string& path, const Nrrd* n, TensorField& f) {
  const int kind = n->axis[0].kind;
  const std::size_t size = n->axis[0].size;
  ComponentLayout l;
  if (kind == nrrdKind3DSymMatrix || (kind == nrrdKindUnknown && size == 6)) {
    l.count = 6;
  } else if (kind == nrrdKind3DMaskedSymMatrix || (kind == nrrdKindUnknown && size == 7)) {
    l.count = 7;
    l.confidence = 0;
    l.sym = {1, 2, 3, 4, 5, 6};
  } else if (kind == nrrdKind3DMatrix || (kind == nrrdKindUnknown && size == 9)) {
    l.count = 9;
    l.full = true;
  } else {
    fail(path, std::string("axis 0 (kind ") + airEnumStr(nrrdKind, kind) + ", size " + std::to_string(size) +
                   ") is not a tensor; expected 3D-symmetric-matrix (6), 3D-masked-symmetric-matrix (7) or 3D-matrix (9)");
  }
  if (size != std::size_t(l.count))
    fail(path, std::string("axis 0 of kind ") + airEnumStr(nrrdKind, kind) + " has size " + std::to_string(size) +
                   ", expected " + std::to_string(l.count));
  f.layout = kind == nrrdKindUnknown ? std::to_string(size) + " values (kind not given)" : airEnumStr(nrrdKind, kind);
  return l;
}

}  // namespace

TensorField impl::readNrrd(const std::string& path, const ReadOptions& opt) {
  const auto h = readHeader(path);
  Nrrd* n = h->nrrd;
  if (n->dim < 3 || n->dim > 4)
    fail(path, "has " + std::to_string(n->dim) + " axes; a tensor volume has 4 (tensor, i, j, k) or 3");
  if (const std::string o = inapplicableOption(InputFormat::Nrrd, opt); !o.empty())
    fail(path, o + " does not apply to NRRD, whose header gives the tensor kind and measurement frame");
  TensorField f;
  f.path = path;
  const ComponentLayout layout = layoutOf(path, n, f);
  f.hasConfidence = layout.confidence >= 0;
  VolumeGeometry g = geometry(path, n, 1, f);
  // As NIfTI's and MRtrix's readers refuse a singular affine: drawn, every
  // glyph along a zero or parallel axis would lie on one plane.
  if (gridIsSingular(g.dims, g.axesWC))
    fail(path, n->spaceDim == 3 ? "the space directions are singular (a zero or parallel direction)"
                                : "the axis spacings are singular (a spacing of 0)");
  const std::uint64_t voxels = std::uint64_t(g.dims[0]) * std::uint64_t(g.dims[1]) * std::uint64_t(g.dims[2]);

  double flip[3];
  toRas(n, g, flip);
  const int space = n->space;
  const std::string target = space == nrrdSpace3DLeftHanded ? "3D-right-handed" : "RAS";
  // "space units": one short word for all three axes, else none is said.
  if (n->spaceDim == 3 && n->spaceUnits[0] && n->spaceUnits[1] && n->spaceUnits[2]) {
    const std::string u = n->spaceUnits[0];
    bool word = !u.empty() && u.size() <= 16 && u == n->spaceUnits[1] && u == n->spaceUnits[2];
    for (const char c : u) word = word && c > ' ' && c < 127;
    if (word) f.lengthUnits = u;
  }
  if (space != nrrdSpaceUnknown) {
    f.space = std::string("RAS");
    if (space != nrrdSpaceRightAnteriorSuperior)
      f.space = flip[0] < 0 ? target + " (converted from " + airEnumStr(nrrdSpace, space) + ")"
                            : std::string(airEnumStr(nrrdSpace, space));
  }
  // NRRD: "measurement frame" vectors are the columns of M (Teem stores
  // measurementFrame[column][row]); D_world = M D Mᵀ. The flip follows.
  std::array<double, 9> t{1, 0, 0, 0, 1, 0, 0, 0, 1};
  if (n->spaceDim == 3 && std::isfinite(n->measurementFrame[0][0])) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) t[3 * r + c] = n->measurementFrame[c][r];
    // A frame is a rotation (or reflection): a singular one would draw every
    // tensor as zero, a scaled one would scale the glyphs unseen.
    double worst = 0;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        double dot = 0;
        for (int r = 0; r < 3; ++r) dot += t[3 * r + a] * t[3 * r + b];
        worst = std::max(worst, std::abs(dot - (a == b ? 1.0 : 0.0)));
      }
    if (!std::isfinite(worst) || !(std::abs(determinant3(t.data())) > 1e-6))
      fail(path, "the measurement frame is singular or not finite");
    if (worst > 1e-3)
      f.warnings.push_back("the measurement frame is not orthonormal (max |MᵀM - I| = " + std::to_string(worst) +
                           "); applied as given, so it scales the tensors");
    f.measurementFrame = t;
  }
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) t[3 * r + c] *= flip[r];
  if (t != std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1}) g.tensorToWC = f.tensorToWC = t;
  f.frame = f.measurementFrame ? "the measurement frame, D = M D Mᵀ"
            : n->spaceDim == 3 ? "the space's axes (no measurement frame)"
                               : "the grid's axes (no space or measurement frame), not rotated";
  if (flip[0] < 0)
    f.frame += std::string("; then ") + (flip[1] < 0 ? "x and y" : "x") + " negated, " +
               airEnumStr(nrrdSpace, space) + " to " + target;

  f.description = std::string("NRRD volume, ") + std::to_string(g.dims[0]) + "x" + std::to_string(g.dims[1]) + "x" +
                  std::to_string(g.dims[2]) + ", " + airEnumStr(nrrdType, n->type) + ", " + h->nio->encoding->name +
                  " encoding";
  const GridPlacement placed = placementOf(g);
  const Selector sel(opt.selection, path, g.dims, &placed);
  const std::uint64_t values = voxels * std::uint64_t(layout.count);
  checkEncodedSize(path, *h, values);
  promiseData("readNrrd", path, opt, values * nrrdTypeSize[n->type], sel.keptBound(voxels));
  if (h->nio->encoding == nrrdEncodingRaw) {
    const int data = fileno(h->nio->dataFile);
    RawSamples raw{util::UniqueFd{}, std::uint64_t(std::ftell(h->nio->dataFile)), rawTypeOf(n->type),
                   nrrdTypeSize[n->type] > 1 && h->nio->endian != airMyEndian(), g, layout};
    // The guard's parent reads the values (io/core/raw_samples.h) from a copy of
    // this descriptor; a mask is read here, beside the data, so that
    // selection stays in the child.
    if (opt.deferRaw && opt.selection.maskPath.empty()) {
      raw.dataFd = util::UniqueFd(::fcntl(data, F_DUPFD_CLOEXEC, 0));
      if (!raw.dataFd) fail(path, std::string("cannot hand the data file over: ") + std::strerror(errno));
      *opt.deferRaw = std::move(raw);
      return f;
    }
    readRawSamples("readNrrd", path, raw, opt, f, data, &sel);
    return f;
  }
  VolumeSink sink(f, g, layout, sel, opt.selection.confidenceMin);
  decode(path, *h, values, std::size_t(layout.count), [&](const double* v, std::size_t m) {
    sink.pushVoxels(v, m);
  });
  sink.finish();
  sink.warnIfAsymmetric();
  return f;
}

ScalarVolume impl::readNrrdScalar(const std::string& path, const int* dims) {
  const auto h = readHeader(path);
  Nrrd* n = h->nrrd;
  if (n->dim != 3) fail(path, "a mask or underlay must have 3 axes, this has " + std::to_string(n->dim));
  ScalarVolume v;
  const std::uint64_t voxels = gridDims(path, n, 0, v.dims);
  if (const std::string m = maskGridMismatch(v.dims, dims); !m.empty()) fail(path, m);
  TensorField unused;
  VolumeGeometry g = geometry(path, n, 0, unused);
  double flip[3];
  toRas(n, g, flip);
  if (n->spaceDim == 3) v.placement = placementOf(g);  // old headers place by spacing alone: unstated
  decode(path, *h, voxels, 1, [&](const double* x, std::size_t m) {
    for (std::size_t i = 0; i < m; ++i) v.values.push_back(float(x[i]));
  });
  return v;
}

}  // namespace tg::io
