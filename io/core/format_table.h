#pragma once
// Input formats as one table: one row per format with its extensions, its
// readers, the module those load and the options and uses that apply. The
// extension checks, the dispatch, the refusal of options a format has no use
// for and the lists in help texts and errors all read it, so a new input
// format is its reader, one row (io/core/format_table.cpp) and its tests.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/core/readers.h"

namespace tg::io {

// The options of ReadOptions a row takes; readers refuse the others
// (inapplicableOption) rather than ignore them.
enum FormatOption : unsigned {
  kLayoutOption = 1,      // --layout
  kFrameOption = 2,       // --frame
  kArrayOption = 4,       // --array
  kConfidenceOption = 8,  // --confidence-min
};

// What a file of a row can be given as.
enum FormatUse : unsigned {
  kTensorUse = 1,      // the input
  kScalarUse = 2,      // --mask and --underlay
  kSurfaceUse = 4,     // --mesh, drawn as it is
  kVolumeMeshUse = 8,  // --mesh, its outer surface
  kFemUse = 16,        // --mesh-from-input: an unstructured grid with cells
  kTractUse = 32,      // --tracts: streamlines (polylines)
};

struct InputFormatRow {
  InputFormat format;  // the family, as readers name themselves to inapplicableOption
  const char* name;    // in messages: "a NIfTI file"
  std::vector<std::string> extensions;  // lower case, with the dot; compressed variants their own (".nii.gz")
  unsigned uses = 0;                    // FormatUse
  unsigned options = 0;                 // FormatOption
  // The module the readers load (io/core/format_modules.h): "vtk", "teem",
  // "nifti", or "" for a reader of our own.
  const char* module = "";
  TensorField (*readTensors)(const std::string& path, const ReadOptions& opt) = nullptr;
  const char* tensorReader = "";  // how the child process is named: "readNrrd"
  ScalarVolume (*readScalars)(const std::string& path, const int dims[3]) = nullptr;
  // Files besides the input that reading it opens (detached data), for
  // filesReadBy; null: none.
  std::vector<std::string> (*dataFiles)(const std::string& path) = nullptr;
};

// "" where the row's module (InputFormatRow::module) is linked in or loads
// on this machine, or is none; else what stops it, as the loader says.
std::string moduleProblem(std::string_view module);

// Every row, in the order help texts and errors list them.
const std::vector<InputFormatRow>& inputFormats();

// The row whose extension `path` ends with (case-insensitive), or null.
const InputFormatRow* inputFormatRowOf(const std::string& path);

// The extensions of the rows with any of `uses`, joined by `sep`, the last by
// `lastSep` (empty: `sep`): ".nrrd .nhdr .nii ...".
std::string extensionList(unsigned uses, const std::string& sep = " ", const std::string& lastSep = "");

// The extension `path` ends with, as a message shows it: ".xyz", or "" when
// its last name has no dot.
std::string shownExtension(const std::string& path);

// The one check every input file gets before a reader sees it: it exists, is
// a regular file (no directory, FIFO or device) and is not empty. Throws
// InputError "<who>: <path>: <problem>"; returns the file's size.
std::uint64_t checkInputFile(const std::string& who, const std::string& path);

}  // namespace tg::io
