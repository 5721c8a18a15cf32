// NRRD through Teem: Teem parses the header (skipData), we check it against
// the file before anything is allocated from it, then decode the data in
// fixed-size chunks straight into the VolumeSink, so that no copy of the
// file's data is ever held.
#include <bzlib.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <teem/air.h>
#include <teem/nrrd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include "io/readers.h"
#include "io/teem_util.h"
#include "io/volume_sink.h"

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
  auto h = std::make_unique<Header>();
  h->nio->skipData = AIR_TRUE;
  h->nio->keepNrrdDataFileOpen = AIR_TRUE;
  if (nrrdLoad(h->nrrd, path.c_str(), h->nio)) {
    // On failure Teem may already have closed the file it left in dataFile
    // (found by fuzz_nrrd: a double fclose); it is not ours to close then.
    h->nio->dataFile = nullptr;
    fail(path, teemNrrdError());
  }
  if (h->nio->format != nrrdFormatNRRD) fail(path, "not a NRRD file");
  if (!h->nio->dataFile) fail(path, "multiple detached data files are not supported");
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

// Streams `count` values into `consume(const double* values, size_t n)`.
template <class Consume>
void decode(const std::string& path, Header& h, std::uint64_t count, Consume&& consume) {
  Nrrd* n = h.nrrd;
  NrrdIoState* nio = h.nio;
  const std::size_t tsize = nrrdTypeSize[n->type];
  const std::uint64_t bytes = count * tsize;
  FILE* file = nio->dataFile;
  const long pos = std::ftell(file);
  const std::uint64_t avail = bytesAfterHeader(h);
  const bool swap = nio->encoding->endianMatters && tsize > 1 && nio->endian != airMyEndian();
  double (*load)(const void*) = nrrdDLoad[n->type];
  std::vector<char> buf(kChunkBytes);
  std::vector<double> vals(kChunkBytes / tsize);
  auto convert = [&](std::size_t got) {
    const std::size_t m = got / tsize;
    for (std::size_t i = 0; i < m; ++i) {
      char* p = buf.data() + i * tsize;
      if (swap) std::reverse(p, p + tsize);
      vals[i] = load(p);
    }
    consume(vals.data(), m);
  };
  auto truncated = [&](std::uint64_t done) {
    fail(path, "data is truncated: the header describes " + std::to_string(bytes) + " bytes, the data ends after " +
                   std::to_string(done));
  };

  if (nio->encoding == nrrdEncodingRaw) {
    if (bytes > avail) truncated(avail);
    for (std::uint64_t done = 0; done < bytes;) {
      const std::size_t want = std::size_t(std::min<std::uint64_t>(kChunkBytes, bytes - done));
      if (std::fread(buf.data(), 1, want, file) != want) truncated(done);
      convert(want);
      done += want;
    }
  } else if (nio->encoding == nrrdEncodingGzip) {
    if (bytes > avail * kMaxGzipRatio) fail(path, "header describes more data than the gzip stream can hold");
    // zlib reads the descriptor from its own offset, so hand it a duplicate
    // positioned where stdio's buffered position says the data begins.
    const int fd = dup(fileno(file));
    if (fd < 0 || lseek(fd, pos, SEEK_SET) != pos) fail(path, "cannot reopen the data file");
    gzFile gz = gzdopen(fd, "rb");
    if (!gz) {
      close(fd);
      fail(path, "cannot open the gzip stream");
    }
    std::unique_ptr<gzFile_s, int (*)(gzFile)> guard(gz, gzclose);
    gzbuffer(gz, 1 << 18);
    // zlib passes non-gzip bytes through unchanged; the header said gzip.
    if (gzdirect(gz)) fail(path, "gzip data is corrupt: no gzip stream where the data begins");
    for (long skip = nio->byteSkip; skip > 0;) {
      const int got = gzread(gz, buf.data(), unsigned(std::min<long>(skip, long(buf.size()))));
      if (got <= 0) fail(path, "gzip data ends inside the byte skip");
      skip -= got;
    }
    for (std::uint64_t done = 0; done < bytes;) {
      const std::size_t want = std::size_t(std::min<std::uint64_t>(kChunkBytes, bytes - done));
      const int got = gzread(gz, buf.data(), unsigned(want));
      if (got < 0) {
        int code = 0;
        fail(path, std::string("gzip data is corrupt: ") + gzerror(gz, &code));
      }
      if (std::size_t(got) != want) truncated(done + std::uint64_t(got));
      convert(want);
      done += want;
    }
  } else if (nio->encoding == nrrdEncodingBzip2) {
    int err = BZ_OK;
    BZFILE* bz = BZ2_bzReadOpen(&err, file, 0, 0, nullptr, 0);
    if (err != BZ_OK) fail(path, "cannot open the bzip2 stream");
    auto closeBz = [&] {
      int e2;
      BZ2_bzReadClose(&e2, bz);
    };
    auto readBz = [&](char* dst, std::size_t want) {
      const int got = BZ2_bzRead(&err, bz, dst, int(want));
      if (err != BZ_OK && err != BZ_STREAM_END) {
        closeBz();
        fail(path, "bzip2 data is corrupt (libbz2 error " + std::to_string(err) + ")");
      }
      return std::size_t(std::max(got, 0));
    };
    for (long skip = nio->byteSkip; skip > 0;) {
      const std::size_t got = readBz(buf.data(), std::size_t(std::min<long>(skip, long(buf.size()))));
      if (got == 0) {
        closeBz();
        fail(path, "bzip2 data ends inside the byte skip");
      }
      skip -= long(got);
    }
    for (std::uint64_t done = 0; done < bytes;) {
      const std::size_t want = std::size_t(std::min<std::uint64_t>(kChunkBytes, bytes - done));
      std::size_t got = 0;
      while (got < want) {
        const std::size_t g = readBz(buf.data() + got, want - got);
        if (g == 0) break;
        got += g;
      }
      if (got != want) {
        closeBz();
        truncated(done + got);
      }
      convert(want);
      done += want;
    }
    closeBz();
  } else if (nio->encoding == nrrdEncodingAscii || nio->encoding == nrrdEncodingHex) {
    // Text holds at least one byte per value (two per byte in hex).
    const std::uint64_t need = nio->encoding == nrrdEncodingHex ? 2 * bytes : count;
    if (need > avail) truncated(avail);
    // Teem's ascii decoder reads each token into a fixed 1 KiB buffer;
    // refuse longer tokens before it sees them.
    if (nio->encoding == nrrdEncodingAscii) {
      std::size_t run = 0;
      for (int c; (c = std::fgetc(file)) != EOF;) {
        run = std::isspace(c) ? 0 : run + 1;
        if (run > 512) fail(path, "ascii data holds a token longer than 512 characters");
      }
      std::clearerr(file);
      std::fseek(file, pos, SEEK_SET);
    }
    const std::size_t chunkValues = kChunkBytes / tsize;
    for (std::uint64_t done = 0; done < count;) {
      const std::size_t want = std::size_t(std::min<std::uint64_t>(chunkValues, count - done));
      if (nio->encoding->read(file, buf.data(), want, n, nio)) fail(path, teemNrrdError());
      for (std::size_t i = 0; i < want; ++i) vals[i] = load(buf.data() + i * tsize);  // native order already
      consume(vals.data(), want);
      done += want;
    }
  } else {
    fail(path, std::string("encoding ") + nio->encoding->name + " is not supported");
  }
}

// Index -> WC from space directions, or for old headers from axis
// spacings or mins/maxs (Teem's nrrdAxisInfoPos honours the centering).
VolumeGeometry geometry(const std::string& path, const Nrrd* n, unsigned first, TensorField& f) {
  VolumeGeometry g;
  for (unsigned k = 0; k < 3; ++k) g.dims[k] = first + k < n->dim ? int(n->axis[first + k].size) : 1;
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
    for (unsigned k = 0; k < 3; ++k) {
      double p0 = 0, step = 1;
      if (first + k < n->dim) {
        const NrrdAxisInfo& ax = n->axis[first + k];
        if (std::isfinite(ax.min) && std::isfinite(ax.max) && ax.size > 1) {
          p0 = nrrdAxisInfoPos(n, first + k, 0);
          step = nrrdAxisInfoPos(n, first + k, 1) - p0;
        } else if (std::isfinite(ax.spacing)) {
          step = ax.spacing;
          if (std::isfinite(ax.min)) p0 = ax.min;
        }
      }
      g.axesWC[4 * k] = step;
      g.originWC[k] = p0;
    }
  } else {
    fail(path, "space of dimension " + std::to_string(n->spaceDim) + " is not supported; tensors need 3");
  }
  return g;
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

TensorField readNrrd(const std::string& path, const ReadOptions& opt) {
  const auto h = readHeader(path);
  Nrrd* n = h->nrrd;
  if (n->dim < 3 || n->dim > 4)
    fail(path, "has " + std::to_string(n->dim) + " axes; a tensor volume has 4 (tensor, i, j, k) or 3");
  TensorField f;
  f.path = path;
  const ComponentLayout layout = layoutOf(path, n, f);
  VolumeGeometry g = geometry(path, n, 1, f);
  const std::uint64_t voxels = std::uint64_t(g.dims[0]) * std::uint64_t(g.dims[1]) * std::uint64_t(g.dims[2]);
  if (voxels > UINT32_MAX) fail(path, "more than 2^32-1 voxels");

  // World space: RAS, with LPS and LAS turned into it; others as given.
  double flip[3] = {1, 1, 1};
  const int space = n->space;
  if (space == nrrdSpaceLeftPosteriorSuperior || space == nrrdSpaceScannerXYZ) flip[0] = flip[1] = -1;
  if (space == nrrdSpaceLeftAnteriorSuperior) flip[0] = -1;
  if (space != nrrdSpaceUnknown) {
    f.space = std::string("RAS");
    if (space != nrrdSpaceRightAnteriorSuperior)
      f.space = flip[0] < 0 ? std::string("RAS (converted from ") + airEnumStr(nrrdSpace, space) + ")"
                            : std::string(airEnumStr(nrrdSpace, space));
  }
  for (int r = 0; r < 3; ++r) {
    g.originWC[r] *= flip[r];
    for (int c = 0; c < 3; ++c) g.axesWC[3 * r + c] *= flip[r];
  }
  // NRRD: "measurement frame" vectors are the columns of M (Teem stores
  // measurementFrame[column][row]); D_world = M D Mᵀ. The flip follows.
  std::array<double, 9> t{1, 0, 0, 0, 1, 0, 0, 0, 1};
  if (n->spaceDim == 3 && std::isfinite(n->measurementFrame[0][0])) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) t[3 * r + c] = n->measurementFrame[c][r];
    f.measurementFrame = t;
  }
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) t[3 * r + c] *= flip[r];
  if (t != std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1}) g.tensorToWC = t;

  f.description = std::string("NRRD volume, ") + std::to_string(g.dims[0]) + "x" + std::to_string(g.dims[1]) + "x" +
                  std::to_string(g.dims[2]) + ", " + airEnumStr(nrrdType, n->type) + ", " + h->nio->encoding->name +
                  " encoding";
  const Selector sel(opt.selection, path, g.dims);
  const std::uint64_t values = voxels * std::uint64_t(layout.count);
  // Reserved up front only where the file has been seen to hold every voxel
  // (found by fuzz_nrrd: a 300-byte header reserved 3.6 GB).
  if (h->nio->encoding == nrrdEncodingRaw && sel.selectsAll() &&
      values * nrrdTypeSize[n->type] <= bytesAfterHeader(*h))
    f.reserve(std::size_t(voxels));
  VolumeSink sink(f, g, layout, sel, opt.selection.confidenceMin);
  std::vector<double> pending;  // a voxel split across two chunks
  decode(path, *h, values, [&](const double* v, std::size_t m) {
    std::size_t i = 0;
    if (!pending.empty()) {
      while (pending.size() < std::size_t(layout.count) && i < m) pending.push_back(v[i++]);
      if (pending.size() < std::size_t(layout.count)) return;
      sink.push(pending.data());
      pending.clear();
    }
    for (; i + layout.count <= m; i += layout.count) sink.push(v + i);
    pending.assign(v + i, v + m);
  });
  sink.finish();
  if (layout.full && sink.maxAsymmetry() > 1e-3)
    f.warnings.push_back("3D-matrix tensors are asymmetric (max |D - Dᵀ| / |D| = " +
                         std::to_string(sink.maxAsymmetry()) + "); drawn symmetrised, (D + Dᵀ)/2");
  return f;
}

ScalarVolume readNrrdScalar(const std::string& path) {
  const auto h = readHeader(path);
  Nrrd* n = h->nrrd;
  if (n->dim != 3) fail(path, "a mask must have 3 axes, this has " + std::to_string(n->dim));
  ScalarVolume v;
  std::uint64_t voxels = 1;
  for (int k = 0; k < 3; ++k) {
    v.dims[k] = int(n->axis[k].size);
    voxels *= n->axis[k].size;
  }
  if (voxels > UINT32_MAX) fail(path, "more than 2^32-1 voxels");
  decode(path, *h, voxels, [&](const double* x, std::size_t m) {
    for (std::size_t i = 0; i < m; ++i) v.values.push_back(float(x[i]));
  });
  return v;
}

}  // namespace tg::io
