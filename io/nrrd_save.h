#pragma once
// Teem's nrrdWrite into an AtomicFile, with every write checked: Teem's own
// nrrdSave ignores the error of the last buffered write at fclose, which is
// where a full disk usually shows.
#include <teem/nrrd.h>

#include <cstdint>
#include <string>

#include "io/atomic_file.h"

namespace tg::io {

// Writes `nrrd` as `nio` says (format NRRD) into `out`, not yet committed,
// and returns the bytes written (for AtomicFile::commit's size check).
// Throws std::runtime_error "CALLER: TARGET: problem".
std::int64_t writeNrrdTo(AtomicFile& out, const Nrrd* nrrd, NrrdIoState* nio, const std::string& caller);

}  // namespace tg::io
