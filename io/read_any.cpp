#include <sys/stat.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

#include "io/guard_wire.h"
#include "io/raw_samples.h"
#include "io/read_guard.h"
#include "io/readers.h"

namespace tg::io {
namespace {

struct Format {
  TensorField (*read)(const std::string&, const ReadOptions&);
  const char* who;
};

Format formatOf(const std::string& path) {
  switch (inputFormatOf(path)) {
    case InputFormat::Vtk: return {readVtk, "readVtk"};
    case InputFormat::Nrrd: return {readNrrd, "readNrrd"};
    case InputFormat::Nifti: return {readNifti, "readNifti"};
    case InputFormat::Mif: return {readMif, "readMif"};
    case InputFormat::Unknown: break;
  }
  const auto dot = path.find_last_of('.');
  const std::string ext = dot == std::string::npos || path.find('/', dot) != std::string::npos ? "" : path.substr(dot);
  throw InputError("readTensorField: " + path + ": unknown extension \"" + ext +
                   "\"; supported: .nrrd .nhdr .nii .nii.gz .mif .mih .vtk .vti .vtu .vtp .vts");
}

std::uint64_t checkedFileSize(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) throw InputError("readTensorField: " + path + ": no such file");
  if (S_ISDIR(st.st_mode)) throw InputError("readTensorField: " + path + ": is a directory");
  if (!S_ISREG(st.st_mode)) throw InputError("readTensorField: " + path + ": not a regular file");
  if (st.st_size == 0) throw InputError("readTensorField: " + path + ": file is empty");
  return std::uint64_t(st.st_size);
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
  checkedFileSize(path);
  return formatOf(path).read(path, opt);
}

TensorField readTensorField(const std::string& path, const ReadOptions& opt) {
  const std::uint64_t size = checkedFileSize(path);
  const Format format = formatOf(path);
  ReadOptions guarded = opt;
  if (!guarded.memoryBudget) guarded.memoryBudget = defaultMemoryBudget();
  // Uncompressed volume data comes back described, not decoded: the child
  // parses the header with the library, this process reads the values
  // (io/raw_samples.h).
  TensorField field;
  std::optional<RawSamples> raw;
  runInChild(
      format.who, path, limitsFor(size, guarded.memoryBudget),
      [&](const PromiseFn& promise) -> SendFn {
        guarded.onPromise = promise;
        auto out = std::make_shared<std::pair<TensorField, std::optional<RawSamples>>>();
        guarded.deferRaw = &out->second;
        out->first = format.read(path, guarded);
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
    readRawSamples(format.who, path, *raw, guarded, field, raw->dataFd.get());
  }
  return field;
}

}  // namespace tg::io
