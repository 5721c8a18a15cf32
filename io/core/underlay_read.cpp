#include <algorithm>
#include <cmath>

#include "io/core/format_table.h"
#include "io/core/read_guard.h"
#include "io/core/readers.h"

namespace tg::io {

ScalarVolume readUnderlay(const std::string& path) {
  auto fail = [&](const std::string& what) { return InputError("readUnderlay: " + path + ": " + what); };
  const std::uint64_t size = checkInputFile("readUnderlay", path);
  const InputFormatRow* row = inputFormatRowOf(path);
  if (!row || !row->readScalars) throw fail("unknown underlay format; use " + extensionList(kScalarUse, ", ", " or "));
  const std::uint64_t budget = defaultMemoryBudget();
  ScalarVolume v = readScalarInChild("readUnderlay", path, limitsFor(size, budget),
                                     [&](const PromiseFn&) { return readScalarVolume(path, nullptr); });
  if (!v.placement)
    throw fail("the file does not say where its voxels lie (no space directions, sform/qform or transform), so it "
               "cannot be lined up with the tensors");
  if (std::none_of(v.values.begin(), v.values.end(), [](float x) { return std::isfinite(x); }))
    throw fail("no finite value");
  return v;
}

}  // namespace tg::io
