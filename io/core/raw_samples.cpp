#include "io/core/raw_samples.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <stdexcept>
#include <vector>

#include "io/core/guard_wire.h"
#include "io/core/selection.h"

namespace tg::io {
namespace {

// Small enough that a chunk and its doubles stay in a core's L2 cache
// between the conversion and the sink: 4 MiB chunks made pushVoxels wait on
// memory for values it had just written.
constexpr std::size_t kChunkBytes = 1 << 17;

template <class U>
U swapBytes(U u) {
  if constexpr (sizeof(U) == 2) return __builtin_bswap16(u);
  else if constexpr (sizeof(U) == 4) return __builtin_bswap32(u);
  else if constexpr (sizeof(U) == 8) return __builtin_bswap64(u);
  else return u;
}

template <class T, bool Swap>
void widen(const char* src, std::size_t m, double* out) {
  using U = std::conditional_t<sizeof(T) == 1, std::uint8_t,
                               std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                                  std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
  for (std::size_t i = 0; i < m; ++i) {
    U u;
    std::memcpy(&u, src + i * sizeof(T), sizeof u);
    if constexpr (Swap) u = swapBytes(u);
    out[i] = double(std::bit_cast<T>(u));
  }
}

template <class T>
void widen(bool swap, const char* src, std::size_t m, double* out) {
  if (swap) widen<T, true>(src, m, out);
  else widen<T, false>(src, m, out);
}

}  // namespace

// One loop per type, which the compiler vectorises, where Teem's loader is
// a call through a pointer for every value (a third of a raw float load).
void rawToDoubles(RawType type, bool swap, const char* src, std::size_t m, double* out) {
  switch (type) {
    case RawType::I8: return widen<std::int8_t>(false, src, m, out);
    case RawType::U8: return widen<std::uint8_t>(false, src, m, out);
    case RawType::I16: return widen<std::int16_t>(swap, src, m, out);
    case RawType::U16: return widen<std::uint16_t>(swap, src, m, out);
    case RawType::I32: return widen<std::int32_t>(swap, src, m, out);
    case RawType::U32: return widen<std::uint32_t>(swap, src, m, out);
    case RawType::I64: return widen<std::int64_t>(swap, src, m, out);
    case RawType::U64: return widen<std::uint64_t>(swap, src, m, out);
    case RawType::F32: return widen<float>(swap, src, m, out);
    case RawType::F64: return widen<double>(swap, src, m, out);
  }
}


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
                    TensorField& f, int dataFd, const Selector* sel) {
  auto fail = [&](const std::string& what) { return InputError(std::string(who) + ": " + path + ": " + what); };
  const VolumeGeometry& g = raw.geometry;
  const std::uint64_t voxels = std::uint64_t(g.dims[0]) * std::uint64_t(g.dims[1]) * std::uint64_t(g.dims[2]);
  const std::size_t tsize = rawTypeBytes(raw.type), count = std::size_t(raw.layout.count);
  const std::uint64_t bytes = voxels * count * tsize;
  // The reader checked this descriptor; checked again, as the child's word.
  struct stat st {};
  if (::fstat(dataFd, &st) != 0 || !S_ISREG(st.st_mode)) throw fail("the data file is not a regular file");
  const std::uint64_t size = std::uint64_t(st.st_size);
  if (raw.offset > size || size - raw.offset < bytes)
    throw fail("data is truncated: the header describes " + std::to_string(bytes) + " bytes, the data ends after " +
               std::to_string(size - std::min(size, raw.offset)));

  std::optional<Selector> own;
  if (!sel) {
    // The file holds every value (checked above), so the kept samples are
    // bounded by it; the budget is checked here all the same.
    const GridPlacement placed = placementOf(g);
    sel = &own.emplace(opt.selection, path, g.dims, &placed);
    promiseData(who, path, opt, bytes, sel->keptBound(voxels));
  }
  if (sel->selectsAll()) f.reserve(std::size_t(voxels));
  VolumeSink sink(f, g, raw.layout, *sel, opt.selection.confidenceMin);
  const bool scaled = !(raw.intercept == 0 && raw.slope == 1);
  const std::size_t record = count * tsize;
  const std::size_t chunk = std::max<std::size_t>(1, kChunkBytes / record) * record;
  std::vector<char> buf(std::size_t(std::min<std::uint64_t>(chunk, bytes)));
  std::vector<double> vals(buf.size() / tsize);
  for (std::uint64_t done = 0, chunks = 0; done < bytes; ++chunks) {
    // Every 4 MiB: a report per 128 KiB chunk would be 400 for 48 MB.
    if (opt.progress && chunks % 32 == 0) opt.progress("loading", double(done), double(bytes), "bytes");
    const std::size_t want = std::size_t(std::min<std::uint64_t>(buf.size(), bytes - done));
    std::size_t got = 0;
    while (got < want) {
      const ssize_t r = ::pread(dataFd, buf.data() + got, want - got, off_t(raw.offset + done + got));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) throw fail("data is truncated: the header describes " + std::to_string(bytes) +
                             " bytes, the data ends after " + std::to_string(done + got));
      got += std::size_t(r);
    }
    const std::size_t m = want / tsize;
    rawToDoubles(raw.type, raw.swap, buf.data(), m, vals.data());
    if (scaled)
      for (std::size_t i = 0; i < m; ++i) vals[i] = raw.intercept + raw.slope * vals[i];
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
  w.passFd(raw->dataFd.get());
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
  w.pod(raw->intercept);
  w.pod(raw->slope);
}

std::optional<RawSamples> receiveRaw(WireIn& r) {
  auto flag = [&r] {
    const auto b = r.pod<std::uint8_t>();
    if (b > 1) throw std::runtime_error("the reader's result is malformed");
    return b == 1;
  };
  if (!flag()) return std::nullopt;
  RawSamples raw;
  raw.dataFd = r.takeFd();
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
  raw.intercept = r.pod<double>();
  raw.slope = r.pod<double>();

  bool ok = type <= std::uint8_t(RawType::F64);
  raw.type = RawType(type);
  std::uint64_t voxels = 1;
  for (int d : g.dims) {
    ok = ok && d >= 1;
    voxels *= std::uint64_t(std::max(d, 1));
    ok = ok && voxels <= (std::uint64_t(1) << 40);
  }
  ok = ok && std::isfinite(raw.intercept) && std::isfinite(raw.slope);
  ok = ok && l.count >= 1 && l.count <= 16 && l.confidence >= -1 && l.confidence < l.count && (!l.full || l.count >= 9);
  for (int s : l.sym) ok = ok && s >= 0 && s < l.count;
  if (!ok) throw std::runtime_error("the reader's result is malformed");
  return raw;
}

}  // namespace tg::io
