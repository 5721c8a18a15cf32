#pragma once
// Third-party parsers (VTK's readers above all, and Teem's and libnifti's
// header parsers) run in a child process, so that a crash, a runaway
// allocation or a hang inside them becomes one line naming the file instead
// of taking the process (or the machine) down. The child has an address-space
// limit, a CPU limit and a wall-clock deadline. Its field comes back through
// a socket, the arrays copied once, straight from the child's memory
// (io/core/guard_wire.h).
#include <cstdint>
#include <functional>
#include <string>

#include "io/core/selection.h"
#include "io/field/tensor_field.h"
#include "util/progress.h"

namespace tg::io {

struct ReadLimits {
  std::uint64_t memoryBytes = 0;  // address space the child may add to what it inherits
  double cpuSeconds = 0;          // CPU time of the child
  double headerSeconds = 0;       // wall time until the reader has promised its data (see ReadBudget)
  double bytesPerSecond = 0;      // then this much more wall time per promised decoded byte
};

// The memory a load may take: 80% of physical memory, and no more than what
// the address-space limit (ulimit -v) leaves beyond what is mapped now.
std::uint64_t defaultMemoryBudget();

// Limits for reading a file of `fileBytes` under `memoryBudget`. Headers are
// small, so the header deadline is short and scales with the file only where
// the format parses everything up front (VTK): 3 s + 1 s per 4 MB.
ReadLimits limitsFor(std::uint64_t fileBytes, std::uint64_t memoryBudget);

// Calls read() in a child process under `limits` (runInChild below). The
// child's stdout and stderr go to /dev/null: a library's own messages never
// reach the user, only the child's InputError does. The PromiseFn given to
// read() is called once the reader's header is checked: it extends the
// deadline by the time `decodedBytes` may take, and lowers the child's
// address-space limit to what it has mapped plus `memoryBytes` (and a fixed
// slack), so that a header that lies about its size cannot allocate beyond
// what it promised. Throws InputError ("who: path: problem") for a crash, a
// limit, a timeout or the reader's own error.
using PromiseFn = std::function<void(std::uint64_t decodedBytes, std::uint64_t memoryBytes)>;

class WireOut;
class WireIn;
// A tensor field on the wire, every member (readTensorField sends the raw
// data's description after it, io/core/raw_samples.h).
void sendField(WireOut& w, const TensorField& f);
TensorField receiveField(WireIn& r);

// A scalar volume (an underlay) read in a child process.
ScalarVolume readScalarInChild(const std::string& who, const std::string& path, const ReadLimits& limits,
                               const std::function<ScalarVolume(const PromiseFn&)>& read);

// Any result: in the child, `read` returns a function that puts its result
// on the wire (holding what it sends alive), and in the parent `receive`
// takes it off. `progress`, if given, hears ("loading", offset, size,
// "bytes") of the file the child reads, about 10 times a second
// (io/core/read_progress.h).
using SendFn = std::function<void(WireOut&)>;
void runInChild(const std::string& who, const std::string& path, const ReadLimits& limits,
                const std::function<SendFn(const PromiseFn&)>& read, const std::function<void(WireIn&)>& receive,
                const util::ProgressSink& progress = {});

}  // namespace tg::io
