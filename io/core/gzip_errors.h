#pragma once
// What a gzip stream read through zlib says when it goes wrong, in the words
// every reader uses (NRRD and NIfTI data): a message without the reader's
// name, which the reader's own fail() puts first.
#include <zlib.h>

#include <string>

namespace tg::io {

// After gzread returned < 0: "gzip data is corrupt: <zlib's reason>",
// without the file name zlib puts before it.
inline std::string gzipReadError(gzFile gz) {
  int code = Z_OK;
  std::string why = gzerror(gz, &code);
  if (const auto colon = why.rfind(": "); colon != std::string::npos) why.erase(0, colon + 2);
  return "gzip data is corrupt: " + why;
}

// After one read past the data (zlib checks the CRC at the stream's end):
// "" when the stream ended with its trailer, else the problem.
inline std::string gzipTrailerError(gzFile gz) {
  int code = Z_OK;
  gzerror(gz, &code);
  return code == Z_OK || code == Z_STREAM_END
             ? std::string()
             : "gzip data is corrupt: the stream ends without its trailer (no CRC to check the data by)";
}

}  // namespace tg::io
