#include "app/output_check.h"

#include "app/scale/cli_values.h"
#include "app/scene_flags.h"
#include "io/core/input_files.h"

namespace tg::app {

std::vector<NamedPath> sceneInputs(const std::string& input, const SceneFlags& flags) {
  std::vector<NamedPath> inputs = {{"INPUT", input}, {"--mask", flags.field.read.selection.maskPath},
                                   {"--underlay", flags.slices.fromField() ? "" : flags.slices.underlay}};
  for (const NamedPath& m : flags.mesh.inputs()) inputs.push_back(m);
  for (const NamedPath& t : flags.tracts.inputs()) inputs.push_back(t);
  return inputs;
}

void refuseOutputsOverInputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const NamedPath& out = outputs[k];
    if (out.path.empty()) continue;
    checkOutputPath(out.flag, out.path);
    for (std::size_t j = 0; j < k; ++j)
      if (!outputs[j].path.empty() && io::sameFile(outputs[j].path, out.path))
        throw UsageError(out.flag + ": \"" + out.path + "\" is also the " + outputs[j].flag + " output");
    for (const NamedPath& in : inputs) {
      if (in.path.empty()) continue;
      for (const std::string& read : io::filesReadBy(in.path)) {
        if (!io::sameFile(read, out.path)) continue;
        if (read == in.path)
          throw UsageError(out.flag + ": \"" + out.path + "\" is the " + in.flag + " file; it would be overwritten");
        throw UsageError(out.flag + ": \"" + out.path + "\" is the data file \"" + read + "\" of " + in.flag + " \"" +
                         in.path + "\"; it would be overwritten");
      }
    }
  }
}

}  // namespace tg::app
