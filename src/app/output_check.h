#pragma once
// Outputs never destroy an input: every path a command will write is checked,
// before any work starts, against every file its inputs read (the INPUT, a
// --mask, and the data files a NRRD header names).
#include <string>
#include <vector>

namespace tg::app {

struct NamedPath {
  std::string flag;  // "-o", "--plot", "INPUT", "--mask", ...
  std::string path;  // empty: not given, skipped
};

struct SceneFlags;

// The files a render of `input` (empty: arrays or the built-in scene) with
// `flags` reads: INPUT, --mask, an --underlay file and every --mesh.
std::vector<NamedPath> sceneInputs(const std::string& input, const SceneFlags& flags);

// Throws UsageError when an output is a directory, lies in a missing
// directory, names the same file as another output, or names a file that
// reading an input opens (by device and inode, so links count too).
void refuseOutputsOverInputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

}  // namespace tg::app
