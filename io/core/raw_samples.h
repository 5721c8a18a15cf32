#pragma once
// Uncompressed voxel data that a reader has located but not decoded. In a
// guarded read (io/core/read_guard.h) the child parses the header with the
// third-party library (Teem) and hands back only this description, with the
// data file it opened and checked as a descriptor (a name could lead to
// another file by then); the parent then reads the values itself, with this
// code of ours, straight into its own memory. Decoded in the child, the samples were written there and
// copied out again, which was a fifth of a guarded load (issue 14's
// 10 M tensors/s/core target). Compressed data stays in the child: there a
// library decodes it.
#include <cstdint>
#include <optional>
#include <string>

#include "io/core/readers.h"
#include "io/core/volume_sink.h"
#include "util/unique_fd.h"

namespace tg::io {

class WireOut;
class WireIn;

enum class RawType : std::uint8_t { I8, U8, I16, U16, I32, U32, I64, U64, F32, F64 };
std::size_t rawTypeBytes(RawType t);
// `m` values of type `type` at `src`, in the other byte order if `swap`, as
// doubles.
void rawToDoubles(RawType type, bool swap, const char* src, std::size_t m, double* out);

struct RawSamples {
  util::UniqueFd dataFd;     // the data file, open: the header's own, or its detached one
  std::uint64_t offset = 0;  // of the first value
  RawType type = RawType::F32;
  bool swap = false;         // stored in the other byte order
  VolumeGeometry geometry;
  ComponentLayout layout;
  // value = intercept + slope * stored (MRtrix's "scaling"), where not 0, 1.
  double intercept = 0, slope = 1;
};

// The voxels of `raw` (layout.count values each, i fastest) through a
// VolumeSink with opt's selection (which must have no mask) into `f`, then
// the sink's finish: what a volume reader does after its header. Errors are
// InputError("who: path: ..."): a data file that is not a regular file or
// that ends before the data. opt.progress hears ("loading", bytes read,
// bytes, "bytes"). `dataFd`: the data file, open (raw.dataFd, or the
// reader's own where it reads in process). `sel`: the reader's selector, its
// promise made (promiseData); null: one is made from opt and the promise
// checked against opt's budget, as the guard's parent does.
void readRawSamples(const char* who, const std::string& path, const RawSamples& raw, const ReadOptions& opt,
                    TensorField& f, int dataFd, const Selector* sel = nullptr);

// On the guard's wire, after the field. receiveRaw checks what the child
// sent before anything is sized from it: std::runtime_error("the reader's
// result is malformed") otherwise.
void sendRaw(WireOut& w, const std::optional<RawSamples>& raw);
std::optional<RawSamples> receiveRaw(WireIn& r);

}  // namespace tg::io
