#pragma once
// Teem's nrrdWrite into an open file (an AtomicFile's, io/field/atomic_file.h), with
// every write checked: Teem's own nrrdSave ignores the error of the last
// buffered write at fclose, which is where a full disk usually shows.
#include <teem/nrrd.h>

#include <cstdint>
#include <string>

namespace tg::io {

// Writes `nrrd` as `nio` says (format NRRD) into the file `fd`, which stands
// for `target`, and returns the bytes written (for AtomicFile::commit's size
// check). Throws std::runtime_error "CALLER: TARGET: problem".
std::int64_t writeNrrdTo(int fd, const std::string& target, const Nrrd* nrrd, NrrdIoState* nio,
                         const std::string& caller);

}  // namespace tg::io
