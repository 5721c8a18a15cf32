#pragma once
// Which files reading an input opens, so that no output can be written over
// one of them (a command checks its outputs against these before any work).
#include <string>
#include <vector>

namespace tg::io {

// `input` itself and, for a NRRD header, every detached data file it names:
// one file, several on the line, a %d-numbered range or a LIST, relative
// names taken from the header's directory. Teem's own field parsers read the
// header; no data file is opened (a FIFO there must not block). Throws
// InputError for a header Teem cannot parse.
std::vector<std::string> filesReadBy(const std::string& input);

// The data files a NRRD header names (empty for attached data or a file
// that is not NRRD); see filesReadBy.
std::vector<std::string> nrrdDataFiles(const std::string& header);

// Whether two paths name the same file: by device and inode when both exist
// (hard and symbolic links included), else by their canonical paths.
bool sameFile(const std::string& a, const std::string& b);

}  // namespace tg::io
