#pragma once
// The scan of a legacy VTK file's text made before VTK reads it: what VTK
// would allocate from, cut short or never return from.
#include <cstdint>
#include <string>

namespace tg::io {

// Every value takes at least one byte (ASCII) or its binary size, so a
// header count beyond the file size is corrupt and a binary file shorter than
// its arrays is truncated; names longer than VTK reads, and runs of spaces
// its ASCII reader never passes, are refused too. The largest point count the
// header states. InputError("readVtk: path: ...").
std::uint64_t checkLegacyCounts(const std::string& path, std::uint64_t fileSize);

}  // namespace tg::io
