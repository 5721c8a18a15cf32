#pragma once
// The paths of the temporary files this process has created and not yet
// committed, so that SIGINT, SIGTERM and SIGHUP remove them before the process
// dies (io/field/atomic_file.h registers and releases them).
namespace tg::io {

// Registers `path` (copied) and installs the signal handlers on first use.
// Returns a slot for releaseTemp; throws std::runtime_error when the registry
// is full or the path too long.
int registerTemp(const char* path);
// Forgets the slot: the path was renamed into place or removed.
void releaseTemp(int slot);

}  // namespace tg::io
