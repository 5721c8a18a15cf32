#include <sys/stat.h>

#include <algorithm>
#include <cmath>

#include "io/read_guard.h"
#include "io/readers.h"

namespace tg::io {

ScalarVolume readUnderlay(const std::string& path) {
  auto fail = [&](const std::string& what) { return InputError("readUnderlay: " + path + ": " + what); };
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw fail("no such file");
  if (S_ISDIR(st.st_mode)) throw fail("is a directory");
  if (!S_ISREG(st.st_mode)) throw fail("not a regular file");
  if (st.st_size == 0) throw fail("file is empty");
  const InputFormat format = inputFormatOf(path);
  const bool vti = path.size() > 4 && (path.ends_with(".vti") || path.ends_with(".VTI"));
  if (format == InputFormat::Unknown || (format == InputFormat::Vtk && !vti))
    throw fail("unknown underlay format; use .nrrd, .nhdr, .nii, .nii.gz, .mif, .mih or .vti");
  const std::uint64_t budget = defaultMemoryBudget();
  ScalarVolume v = readScalarInChild("readUnderlay", path, limitsFor(std::uint64_t(st.st_size), budget),
                                     [&](const PromiseFn&) { return readScalarVolume(path, nullptr); });
  if (!v.placement)
    throw fail("the file does not say where its voxels lie (no space directions, sform/qform or transform), so it "
               "cannot be lined up with the tensors");
  if (std::none_of(v.values.begin(), v.values.end(), [](float x) { return std::isfinite(x); }))
    throw fail("no finite value");
  return v;
}

}  // namespace tg::io
