// readTracts's guarded child and the checks it makes first; VTK polylines
// are read by the VTK module (io/modules/vtk/mesh_reader.cpp, io/core/format_modules.h), .tck
// and .trk by our own readers (io/core/tck_reader.cpp, io/core/trk_reader.cpp).
#include <algorithm>
#include <memory>

#include "io/core/format_modules.h"
#include "io/core/format_table.h"
#include "io/core/guard_wire.h"
#include "io/core/mesh_reader.h"
#include "io/core/read_guard.h"
#include "io/core/tract_reader.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readTracts: " + path + ": " + what);
}

constexpr std::uint32_t kTractWireMagic = 0x54475431;  // "TGT1"

TractData readAny(const std::string& path, std::uint64_t budget, const PromiseFn& promise) {
  checkInputFile("readTracts", path);
  if (const std::string problem = tractExtensionProblem(path); !problem.empty()) fail(path, problem);
  const std::string ext = meshExtension(path);
  if (ext == "tck") return readTck(path, budget, promise);
  if (ext == "trk") return readTrk(path, budget, promise);
  return vtkFormats("readTracts", path).readTracts(path, budget, promise);
}

}  // namespace

std::string tractExtensionProblem(const std::string& path) {
  const InputFormatRow* row = inputFormatRowOf(path);
  if (row && row->uses & kTractUse) return "";
  return "unknown tractography extension \"" + shownExtension(path) + "\"; supported: " + extensionList(kTractUse);
}

TractData readTractsInProcess(const std::string& path, std::uint64_t memoryBudget) {
  return readAny(path, memoryBudget, {});
}

TractData readTracts(const std::string& path) {
  const std::uint64_t size = checkInputFile("readTracts", path);
  if (const std::string problem = tractExtensionProblem(path); !problem.empty()) fail(path, problem);
  const std::uint64_t budget = defaultMemoryBudget();
  TractData out;
  runInChild(
      "readTracts", path, limitsFor(size, budget),
      [&](const PromiseFn& promise) -> SendFn {
        auto t = std::make_shared<const TractData>(readAny(path, budget, promise));
        return [t](WireOut& w) {
          w.pod(kTractWireMagic);
          w.str(t->path);
          w.str(t->description);
          w.str(t->warning);
          w.pod(std::uint64_t(t->skippedNonFinite));
          w.array(t->positionsWC);
          w.array(t->starts);
        };
      },
      [&](WireIn& in) {
        if (in.pod<std::uint32_t>() != kTractWireMagic) throw std::runtime_error("the reader's result is malformed");
        out.path = in.str();
        out.description = in.str();
        out.warning = in.str();
        out.skippedNonFinite = std::size_t(in.pod<std::uint64_t>());
        in.array(out.positionsWC);
        in.array(out.starts);
      });
  // Checked where they are used: starts that do not rise from 0 to the
  // point count would index past the points.
  const std::uint64_t n = out.pointCount();
  bool ok = out.positionsWC.size() % 3 == 0 && !out.starts.empty() && out.starts[0] == 0 &&
            out.starts[out.starts.size() - 1] == n && n <= kMaxTractPoints;
  for (std::size_t k = 1; ok && k < out.starts.size(); ++k) ok = out.starts[k - 1] <= out.starts[k];
  if (!ok) fail(path, "the reader's streamlines index past its points");
  return out;
}

}  // namespace tg::io
