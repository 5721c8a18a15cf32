#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

#include "io/core/format_table.h"
#include "io/core/guard_wire.h"
#include "io/core/raw_samples.h"
#include "io/core/read_guard.h"
#include "io/core/readers.h"

namespace tg::io {
namespace {

// The row that reads `path`'s tensors, or the one-line refusal.
const InputFormatRow& formatOf(const std::string& path) {
  const InputFormatRow* row = inputFormatRowOf(path);
  if (row && row->readTensors) return *row;
  if (row && row->uses & kTractUse)
    throw InputError("readTensorField: " + path + ": " + row->name + " holds streamlines, not tensors: give it with "
                     "--tracts beside a tensor input");
  throw InputError("readTensorField: " + path + ": unknown extension \"" + shownExtension(path) +
                   "\"; supported: " + extensionList(kTensorUse));
}

}  // namespace

void promiseData(const char* who, const std::string& path, const ReadOptions& opt, std::uint64_t decodedBytes,
                 std::uint64_t keptSamples, std::uint64_t libraryBytes) {
  const std::uint64_t budget = opt.memoryBudget;
  // In long double: a hostile header's counts must not wrap the product.
  const long double need = (long double)keptSamples * kPeakBytesPerTensor + (long double)libraryBytes;
  if (budget && need > (long double)budget)
    throw InputError(std::string(who) + ": " + path + ": " + std::to_string(keptSamples) + " tensors would need " +
                     std::to_string(std::uint64_t(need / (1 << 20))) + " MiB, more than the " +
                     std::to_string(budget >> 20) + " MiB this load may use (select fewer with --slice or --stride)");
  if (opt.onPromise) opt.onPromise(decodedBytes, std::uint64_t(std::min<long double>(need, 1e19L)));
}

TensorField readTensorFieldInProcess(const std::string& path, const ReadOptions& opt) {
  checkInputFile("readTensorField", path);
  TensorField f = formatOf(path).readTensors(path, opt);
  applyTensorAxes(f, opt.tensorAxes);
  return f;
}

TensorField readTensorField(const std::string& path, const ReadOptions& opt) {
  const std::uint64_t size = checkInputFile("readTensorField", path);
  const InputFormatRow& format = formatOf(path);
  ReadOptions guarded = opt;
  if (!guarded.memoryBudget) guarded.memoryBudget = defaultMemoryBudget();
  // Uncompressed volume data comes back described, not decoded: the child
  // parses the header with the library, this process reads the values
  // (io/core/raw_samples.h).
  TensorField field;
  std::optional<RawSamples> raw;
  runInChild(
      format.tensorReader, path, limitsFor(size, guarded.memoryBudget),
      [&](const PromiseFn& promise) -> SendFn {
        guarded.onPromise = promise;
        auto out = std::make_shared<std::pair<TensorField, std::optional<RawSamples>>>();
        guarded.deferRaw = &out->second;
        out->first = format.readTensors(path, guarded);
        return [out](WireOut& w) {
          sendField(w, out->first);
          sendRaw(w, out->second);
        };
      },
      [&](WireIn& in) {
        field = receiveField(in);
        raw = receiveRaw(in);
      },
      opt.progress);
  if (raw) {
    guarded.onPromise = nullptr;
    readRawSamples(format.tensorReader, path, *raw, guarded, field, raw->dataFd.get());
  }
  applyTensorAxes(field, opt.tensorAxes);
  return field;
}

}  // namespace tg::io
