// nrrdDataFiles (io/core/input_files.h), in the Teem module (io/core/format_modules.h).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <teem/air.h>
#include <teem/nrrd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "io/core/format_impl.h"
#include "io/modules/teem/teem_util.h"

namespace tg::io {
namespace {

// A %d-numbered data file list longer than this is refused rather than spelt out.
constexpr unsigned kMaxDataFiles = 100000;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("nrrdDataFiles: " + path + ": " + what);
}

struct HeaderState {
  Nrrd* nrrd = nrrdNew();
  NrrdIoState* nio = nrrdIoStateNew();
  FILE* file = nullptr;
  ~HeaderState() {
    if (file) std::fclose(file);
    nrrdIoStateNix(nio);
    nrrdNuke(nrrd);
  }
};

// Opens a regular file without blocking on a FIFO or device at that name.
FILE* openRegular(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return nullptr;
  struct stat st {};
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    close(fd);
    return nullptr;
  }
  fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  FILE* f = fdopen(fd, "rb");
  if (!f) close(fd);
  return f;
}

// The name a "%d"-style format gives `index`: Teem passes the header's format
// string to sprintf; here only one %d (with flags and width) is substituted.
std::string numbered(const std::string& header, const std::string& format, long long index) {
  const auto pct = format.find('%');
  auto end = format.find_first_not_of("0123456789+- ", pct + 1);
  if (pct == std::string::npos || end == std::string::npos || format[end] != 'd' ||
      format.find('%', end + 1) != std::string::npos)
    throw impl::NrrdDataFilesRefused("nrrdDataFiles: " + header + ": data file format \"" + format +
                               "\" needs exactly one %d");
  std::string spec(1, '%');
  spec.append(format, pct + 1, end - pct - 1).append("lld");
  char num[64];
  std::snprintf(num, sizeof num, spec.c_str(), index);
  std::string name = format.substr(0, pct);
  return name.append(num).append(format, end + 1);
}

std::string resolved(const std::string& dir, const std::string& name) {
  return name.front() == '/' ? name : (std::filesystem::path(dir) / name).string();
}

[[noreturn]] void tooManyDataFiles(const std::string& header, unsigned long long n) {
  throw impl::NrrdDataFilesRefused("nrrdDataFiles: " + header + ": " + std::to_string(n) + " data files; at most " +
                                   std::to_string(kMaxDataFiles) + " are accepted");
}

// How many files MIN..MAX by STEP names, refused beyond kMaxDataFiles.
unsigned long long rangeCount(const std::string& header, long long lo, long long hi, long long step) {
  if (step == 0 || (hi - lo) / step < 0)
    throw impl::NrrdDataFilesRefused("nrrdDataFiles: " + header + ": data file range is empty or its step is 0");
  const unsigned long long n = static_cast<unsigned long long>((hi - lo) / step) + 1;
  if (n > kMaxDataFiles) tooManyDataFiles(header, n);
  return n;
}

bool isList(const char* value) { return std::strncmp(value, "LIST", 4) == 0; }

// Bounds on what a LIST may hold after its line, as on a header (below).
constexpr std::size_t kMaxListLine = 1 << 20, kMaxListBytes = 16 << 20;

// "data file: LIST [SUBDIM]": every later line names one data file, as
// Teem reads them (an empty line too, which names none), lines ending as
// airOneLine ends them. Not through Teem's parser, which grows its array of
// names by a fixed step, copying it each time: a header of a million names
// took minutes before any limit could say no. Here each line is counted as
// it is read and kept only while within kMaxDataFiles; past it the rest are
// only counted, and the whole is refused with their number. Lines and their
// sum are bounded, as the header before them is.
std::vector<std::string> listedDataFiles(const std::string& header, const std::string& dir, FILE* in) {
  std::vector<std::string> files;
  unsigned long long count = 0;
  std::size_t total = 0;
  std::string name;
  bool any = false;  // a line begun since the last end of line
  auto endLine = [&] {
    if (++count <= kMaxDataFiles && !name.empty() && name != "-") files.push_back(resolved(dir, name));
    name.clear();
    any = false;
  };
  for (int c; (c = std::fgetc(in)) != EOF;) {
    if (++total > kMaxListBytes) fail(header, "its LIST of data files is longer than 16 MiB");
    if (c == '\r') {
      const int next = std::fgetc(in);
      if (next != '\n' && next != EOF) std::ungetc(next, in);
      c = '\n';
    }
    if (c == '\n') {
      endLine();
      continue;
    }
    any = true;
    if (count < kMaxDataFiles) {
      if (name.size() >= kMaxListLine) fail(header, "a name in its LIST of data files is longer than 1 MiB");
      name.push_back(char(c));
    }
  }
  if (any) endLine();
  if (count > kMaxDataFiles) tooManyDataFiles(header, count);
  return files;
}

// A "%d"-style "data file: FORMAT MIN MAX STEP" line's count, before Teem's
// parser sees it: the parser steps through every index (_nrrdDataFNNumber),
// and "0 1999999999 1" took seconds before any limit could say no.
void checkDataFileRange(const std::string& header, const char* value) {
  std::istringstream in(value);
  std::string format;
  long long lo = 0, hi = 0, step = 0;
  if (in >> format >> lo >> hi >> step && format.find('%') != std::string::npos) rangeCount(header, lo, hi, step);
}

// Teem adds each key:=value pair with a linear search of those before it, so
// a header of 200k pairs took 84 s (and 300k comment lines 4 s); real
// headers have a few dozen.
constexpr std::size_t kMaxKeyValues = 4096;
// Teem's biff formats each error into a 1 KiB stack buffer with vsprintf,
// and the field parsers quote the line they refuse: a field line of about
// 1.1 KB overflowed it, and glibc's fortify check aborted the process (the
// parent too, which lists an input's data files to protect them from -o).
// Real field lines stay under 300 bytes (space directions at 17 digits);
// comments, key:=value pairs and content are never quoted, and may be long.
constexpr std::size_t kMaxFieldLine = 512;
// Teem reads each line whole into memory, in the parent too: bounds on any
// line and on the header, far beyond real headers, keep a file of one
// endless line or line after line from costing memory or time.
constexpr std::size_t kMaxLine = 1 << 20, kMaxHeader = 16 << 20;

// Teem reads any format it knows from a file's first line: plain text,
// VTK, PNM, PNG. Their parsers quote whole lines into biff's 1 KiB stack
// buffer, and this check knows only NRRD's lines (a plain-text .nrrd whose
// "# old min: " comment was 1.5 KB aborted the reader). A .nrrd or .nhdr
// must begin with NRRD's magic, as Teem's NRRD format tells it.
void checkMagic(const char* who, const std::string& path, const std::string& first) {
  NrrdIoState* nio = nrrdIoStateNew();
  airFree(nio->line);
  nio->line = airStrdup(first.c_str());
  const bool nrrd = nrrdFormatNRRD->contentStartsLike(nio);
  nrrdIoStateNix(nio);
  if (!nrrd) throw InputError(std::string(who) + ": " + path + ": not a NRRD file (line 1 is not NRRD0001 to NRRD0006)");
}

}  // namespace

void impl::checkNrrdHeaderText(const char* who, const std::string& path, FILE* in) {
  auto refuse = [&](const std::string& what) { throw InputError(std::string(who) + ": " + path + ": " + what); };
  std::size_t pairs = 0, comments = 0, line = 1, length = 0, total = 0;
  bool free = false, field = false;  // this line: free text (comment, key:=value, content); a "key: " seen
  std::string start, magic;
  int prev = '\n';
  // Line 1 is the magic, which Teem quotes only in part.
  auto check = [&] {
    if (!free && line > 1 && length > kMaxFieldLine)
      refuse("header line " + std::to_string(line) + " is " + std::to_string(length) + " bytes long; only comments, " +
             "key:=value pairs and content may be longer than " + std::to_string(kMaxFieldLine));
  };
  // Lines end as Teem's airOneLine ends them: at "\n", "\r\n" or a lone
  // "\r" (a comment holding a "\r" hid a long field line from this check).
  // The header ends at its first empty line.
  for (int c; (c = std::fgetc(in)) != EOF; prev = c) {
    if (c == '\r') {
      const int next = std::fgetc(in);
      if (next != '\n' && next != EOF) std::ungetc(next, in);
      c = '\n';
    }
    if (c == '\n') {
      if (length == 0) break;
      if (line == 1) checkMagic(who, path, magic);
      check();
      ++line;
      length = 0;
      free = field = false;
      start.clear();
      continue;
    }
    ++length;
    // Teem's lines are C strings put together from pieces: a NUL cuts a
    // piece short, and this check would judge other text than Teem's (a
    // ":=" after a NUL made a 1.5 KB line free text here, and Teem quoted
    // the rest as a line it could not parse).
    if (c == '\0') refuse("header line " + std::to_string(line) + " holds a NUL byte");
    if (line == 1 && magic.size() < 16) magic.push_back(char(c));
    if (++total > kMaxHeader) refuse("header has no empty line ending it within its first 16 MiB");
    if (length > kMaxLine) refuse("header line " + std::to_string(line) + " is longer than 1 MiB");
    if (length == 1 && c == '#') {
      free = true;
      if (++comments > kMaxKeyValues)
        refuse("header has more than " + std::to_string(kMaxKeyValues) + " comment lines");
    }
    if (c == '=' && prev == ':') {
      free |= !field;
      if (++pairs > kMaxKeyValues) refuse("header has more than " + std::to_string(kMaxKeyValues) + " key:=value pairs");
    }
    field |= c == ' ' && prev == ':';
    // Teem finds the field at the line's first ": "; "content:" followed by
    // anything else is a line it refuses, quoting it.
    if (start.size() < 9) {
      start.push_back(char(c));
      free |= start == "content: ";
    }
  }
  if (line == 1) checkMagic(who, path, magic);
  check();
  std::clearerr(in);
  std::rewind(in);
}

std::vector<std::string> impl::nrrdDataFiles(const std::string& header) {
  HeaderState h;
  h.file = openRegular(header);
  if (!h.file) return {};  // missing or not a regular file: the reader says so
  checkNrrdHeaderText("nrrdDataFiles", header, h.file);
  const std::filesystem::path hp(header);
  const std::string dir = hp.has_parent_path() ? hp.parent_path().string() : ".";
  unsigned len = 0;
  if (_nrrdOneLine(&len, h.nio, h.file) || len == 0 || !nrrdFormatNRRD->contentStartsLike(h.nio))
    return {};  // not NRRD: the reader says so
  // Teem's header loop (_nrrdFormatNRRD_read) up to its "data file" field,
  // without the step that opens the data files. Comments and key:=value
  // lines are skipped (nothing here needs them, and Teem's key/value list
  // grows quadratically); every other field goes through Teem's own parser.
  // A LIST is read here (listedDataFiles); the reader's nrrdLoad checks the
  // header that comes before it.
  for (;;) {
    h.nio->pos = 0;
    if (_nrrdOneLine(&len, h.nio, h.file)) fail(header, teemNrrdError());
    if (len <= 1) return {};  // end of the header: the data is attached
    const char* line = h.nio->line;
    const char* colon = std::strstr(line, ": ");
    if (line[0] == '#' || !colon) continue;  // comments, key:=value, or lines the reader refuses
    const int field = airEnumVal(nrrdField, std::string(line, colon).c_str());
    if (field == nrrdField_unknown || field == nrrdField_comment || field == nrrdField_keyvalue) continue;
    if (h.nio->seen[field]) fail(header, std::string("field \"") + airEnumStr(nrrdField, field) + "\" given twice");
    h.nio->pos = int(colon + 2 - line + std::strspn(colon + 2, " \t"));
    if (field == nrrdField_data_file && isList(line + h.nio->pos)) return listedDataFiles(header, dir, h.file);
    if (field == nrrdField_data_file) checkDataFileRange(header, line + h.nio->pos);
    if (nrrdFieldInfoParse[field](h.file, h.nrrd, h.nio, AIR_TRUE)) fail(header, teemNrrdError());
    h.nio->seen[field] = AIR_TRUE;
    if (field == nrrdField_data_file) break;
  }
  std::vector<std::string> files;
  if (h.nio->dataFNFormat) {
    const long long step = h.nio->dataFNStep, lo = h.nio->dataFNMin, hi = h.nio->dataFNMax;
    const unsigned long long n = rangeCount(header, lo, hi, step);
    for (long long i = lo, k = 0; static_cast<unsigned long long>(k) < n; i += step, ++k)
      files.push_back(resolved(dir, numbered(header, h.nio->dataFNFormat, i)));
  } else {
    for (unsigned k = 0; k < h.nio->dataFNArr->len; ++k) {
      const std::string name = h.nio->dataFN[k];
      if (!name.empty() && name != "-") files.push_back(resolved(dir, name));
    }
  }
  return files;
}

}  // namespace tg::io
