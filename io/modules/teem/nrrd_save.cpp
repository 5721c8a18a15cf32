#include "io/modules/teem/nrrd_save.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "io/modules/teem/teem_util.h"

namespace tg::io {

std::int64_t writeNrrdTo(int out, const std::string& target, const Nrrd* nrrd, NrrdIoState* nio,
                         const std::string& caller) {
  auto fail = [&](const std::string& what) { throw std::runtime_error(caller + ": " + target + ": " + what); };
  const int fd = dup(out);
  FILE* file = fd >= 0 ? fdopen(fd, "wb") : nullptr;
  if (!file) {
    if (fd >= 0) close(fd);
    fail(std::string("cannot write: ") + std::strerror(errno));
  }
  nrrdIoStateFormatSet(nio, nrrdFormatNRRD);
  const int err = nrrdWrite(file, nrrd, nio);
  const std::string teemError = err ? teemNrrdError() : "";
  const bool flushed = std::fflush(file) == 0 && !std::ferror(file);
  const int flushErrno = errno;
  const long size = std::ftell(file);
  const bool closed = std::fclose(file) == 0;
  if (err) fail(teemError);
  if (!flushed || !closed) fail(std::string("write failed: ") + std::strerror(flushErrno));
  return size;
}

}  // namespace tg::io
