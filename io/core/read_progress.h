#pragma once
// How far a guarded reader (io/core/read_guard.h) has come, seen from the parent
// without touching the readers: the file offset of the largest regular file
// the child has open (/proc/PID/fdinfo), against that file's size. Teem,
// libnifti, VTK and our own readers all read their data through a file
// descriptor, so this follows every format, compressed ones by their
// compressed bytes.
#include <sys/types.h>

#include <cstdint>
#include <optional>

namespace tg::io {

struct ReadPosition {
  std::uint64_t offset = 0, size = 0;
};

// Nothing when the child has no regular file open or /proc cannot tell.
std::optional<ReadPosition> childReadPosition(pid_t child);

}  // namespace tg::io
