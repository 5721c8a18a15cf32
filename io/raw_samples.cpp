#include "io/raw_samples.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "io/guard_wire.h"
#include "io/selection.h"

namespace tg::io {
namespace {

// Small enough that a chunk and its doubles stay in a core's L2 cache
// between the conversion and the sink: 4 MiB chunks made pushVoxels wait on
// memory for values it had just written.
constexpr std::size_t kChunkBytes = 1 << 17;

template <class T>
void widen(const char* src, std::size_t m, double* out) {
  for (std::size_t i = 0; i < m; ++i) {
    T v;
    std::memcpy(&v, src + i * sizeof(T), sizeof v);
    out[i] = double(v);
  }
}

}  // namespace

// One loop per type, which the compiler vectorises, where Teem's loader is
// a call through a pointer for every value (a third of a raw float load).
void rawToDoubles(RawType type, const char* src, std::size_t m, double* out) {
  switch (type) {
    case RawType::I8: return widen<std::int8_t>(src, m, out);
    case RawType::U8: return widen<std::uint8_t>(src, m, out);
    case RawType::I16: return widen<std::int16_t>(src, m, out);
    case RawType::U16: return widen<std::uint16_t>(src, m, out);
    case RawType::I32: return widen<std::int32_t>(src, m, out);
    case RawType::U32: return widen<std::uint32_t>(src, m, out);
    case RawType::I64: return widen<std::int64_t>(src, m, out);
    case RawType::U64: return widen<std::uint64_t>(src, m, out);
    case RawType::F32: return widen<float>(src, m, out);
    case RawType::F64: return widen<double>(src, m, out);
  }
}

namespace {

struct Fd {
  int fd = -1;
  bool owned = true;
  ~Fd() {
    if (fd >= 0 && owned) ::close(fd);
  }
};

}  // namespace

std::size_t rawTypeBytes(RawType t) {
  switch (t) {
    case RawType::I8:
    case RawType::U8: return 1;
    case RawType::I16:
    case RawType::U16: return 2;
    case RawType::I32:
    case RawType::U32:
    case RawType::F32: return 4;
    case RawType::I64:
    case RawType::U64:
    case RawType::F64: return 8;
  }
  return 0;
}

void readRawSamples(const char* who, const std::string& path, const RawSamples& raw, const ReadOptions& opt,
                    TensorField& f, int dataFd) {
  auto fail = [&](const std::string& what) { return InputError(std::string(who) + ": " + path + ": " + what); };
  const VolumeGeometry& g = raw.geometry;
  const std::uint64_t voxels = std::uint64_t(g.dims[0]) * std::uint64_t(g.dims[1]) * std::uint64_t(g.dims[2]);
  const std::size_t tsize = rawTypeBytes(raw.type), count = std::size_t(raw.layout.count);
  const std::uint64_t bytes = voxels * count * tsize;
  // Non-blocking: a data file swapped for a FIFO since the header was read
  // must not hang the open; only a regular file passes the check after it.
  Fd in = dataFd >= 0 ? Fd{dataFd, false} : Fd{::open(raw.dataPath.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  struct stat st {};
  if (in.fd < 0) throw fail("cannot open the data file " + raw.dataPath + ": " + std::strerror(errno));
  if (::fstat(in.fd, &st) != 0 || !S_ISREG(st.st_mode)) throw fail("the data file is not a regular file");
  const std::uint64_t size = std::uint64_t(st.st_size);
  if (raw.offset > size || size - raw.offset < bytes)
    throw fail("data is truncated: the header describes " + std::to_string(bytes) + " bytes, the data ends after " +
               std::to_string(size - std::min(size, raw.offset)));

  const GridPlacement placed = placementOf(g);
  const Selector sel(opt.selection, path, g.dims, &placed);
  // The file holds every value (checked above), so the kept samples are
  // bounded by it; the budget is checked again all the same.
  promiseData(who, path, opt, bytes, sel.keptBound(voxels));
  if (sel.selectsAll()) f.reserve(std::size_t(voxels));
  VolumeSink sink(f, g, raw.layout, sel, opt.selection.confidenceMin);
  const std::size_t record = count * tsize;
  const std::size_t chunk = std::max<std::size_t>(1, kChunkBytes / record) * record;
  std::vector<char> buf(std::size_t(std::min<std::uint64_t>(chunk, bytes)));
  std::vector<double> vals(buf.size() / tsize);
  for (std::uint64_t done = 0; done < bytes;) {
    if (opt.progress) opt.progress("loading", double(done), double(bytes), "bytes");
    const std::size_t want = std::size_t(std::min<std::uint64_t>(buf.size(), bytes - done));
    std::size_t got = 0;
    while (got < want) {
      const ssize_t r = ::pread(in.fd, buf.data() + got, want - got, off_t(raw.offset + done + got));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) throw fail("data is truncated: the header describes " + std::to_string(bytes) +
                             " bytes, the data ends after " + std::to_string(done + got));
      got += std::size_t(r);
    }
    const std::size_t m = want / tsize;
    if (raw.swap)
      for (std::size_t i = 0; i < m; ++i) std::reverse(buf.data() + i * tsize, buf.data() + (i + 1) * tsize);
    rawToDoubles(raw.type, buf.data(), m, vals.data());
    sink.pushVoxels(vals.data(), m);
    done += want;
  }
  if (opt.progress) opt.progress("loading", double(bytes), double(bytes), "bytes");
  sink.finish();
  sink.warnIfAsymmetric();
}

// ---- The wire ---------------------------------------------------------------

void sendRaw(WireOut& w, const std::optional<RawSamples>& raw) {
  w.pod(std::uint8_t(raw.has_value()));
  if (!raw) return;
  w.str(raw->dataPath);
  w.pod(raw->offset);
  w.pod(std::uint8_t(raw->type));
  w.pod(std::uint8_t(raw->swap));
  const VolumeGeometry& g = raw->geometry;
  w.pod(g.dims);
  w.pod(g.originWC);
  w.pod(g.axesWC);
  w.pod(std::uint8_t(g.tensorToWC.has_value()));
  if (g.tensorToWC) w.pod(*g.tensorToWC);
  const ComponentLayout& l = raw->layout;
  w.pod(l.count);
  w.pod(l.confidence);
  w.pod(std::uint8_t(l.full));
  w.pod(l.sym);
}

std::optional<RawSamples> receiveRaw(WireIn& r) {
  auto flag = [&r] {
    const auto b = r.pod<std::uint8_t>();
    if (b > 1) throw std::runtime_error("the reader's result is malformed");
    return b == 1;
  };
  if (!flag()) return std::nullopt;
  RawSamples raw;
  raw.dataPath = r.str();
  raw.offset = r.pod<std::uint64_t>();
  const auto type = r.pod<std::uint8_t>();
  raw.swap = flag();
  VolumeGeometry& g = raw.geometry;
  r.bytes(g.dims, sizeof g.dims);
  r.bytes(g.originWC, sizeof g.originWC);
  r.bytes(g.axesWC, sizeof g.axesWC);
  if (flag()) g.tensorToWC = r.pod<std::array<double, 9>>();
  ComponentLayout& l = raw.layout;
  l.count = r.pod<int>();
  l.confidence = r.pod<int>();
  l.full = flag();
  l.sym = r.pod<std::array<int, 6>>();

  bool ok = !raw.dataPath.empty() && raw.dataPath.front() == '/' &&
            raw.dataPath.find('\0') == std::string::npos && type <= std::uint8_t(RawType::F64);
  raw.type = RawType(type);
  std::uint64_t voxels = 1;
  for (int d : g.dims) {
    ok = ok && d >= 1;
    voxels *= std::uint64_t(std::max(d, 1));
    ok = ok && voxels <= (std::uint64_t(1) << 40);
  }
  ok = ok && l.count >= 1 && l.count <= 16 && l.confidence >= -1 && l.confidence < l.count && (!l.full || l.count >= 9);
  for (int s : l.sym) ok = ok && s >= 0 && s < l.count;
  if (!ok) throw std::runtime_error("the reader's result is malformed");
  return raw;
}

}  // namespace tg::io
