#pragma once
// Output that appears whole or not at all. The bytes go to a new file created
// exclusively beside the target under a random name (never through a link that
// someone planted there), every write is checked, and commit() syncs the file,
// renames it over the target and syncs the directory. Until then the temporary
// file is removed on any failure, exception or SIGINT/SIGTERM/SIGHUP
// (io/field/temp_registry.h).
#include <cstdint>
#include <functional>
#include <string>

namespace tg::io {

class AtomicFile {
 public:
  // Creates the temporary file "DIR/.NAME-RANDOM.tmp.EXT" for `target`
  // "DIR/NAME.EXT" (the extension kept, for writers that choose a format by
  // it). Throws std::runtime_error "AtomicFile: TARGET: problem", also for a
  // target that unwritableTarget refuses (checked again at commit).
  explicit AtomicFile(const std::string& target);
  // A file that keeps its unique name "DIR/STEM.RANDOM.EXT": the data file of
  // a pair, committed by the header that names it (keep()).
  struct UniqueName {};
  AtomicFile(UniqueName, const std::string& dir, const std::string& stem, const std::string& ext);
  ~AtomicFile();  // removes the file unless committed or kept
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& target() const { return target_; }
  const std::string& tempPath() const { return temp_; }
  // Open for reading and writing. Writers that need a path (Teem, VTK, OIIO
  // without an I/O proxy) may reopen tempPath(); commit() checks that the
  // file there is still the one created here.
  int fd() const { return fd_; }
  // All `n` bytes at the current offset, or throws (disk full, I/O error).
  void write(const void* data, std::size_t n);
  std::uint64_t bytesWritten() const { return written_; }

  // fsync, close, rename over the target, fsync the directory. With
  // `expectedSize`, the file must hold exactly that many bytes.
  void commit(std::int64_t expectedSize = -1);
  // As commit(), but the file is exchanged with the target (renameat2
  // RENAME_EXCHANGE), so that the displaced file is known exactly even with
  // concurrent writers: `displaced(path)` sees it before it is removed.
  void commitExchange(std::int64_t expectedSize, const std::function<void(const std::string& displaced)>& displaced);
  // fsync and close, keeping the file under its own name.
  void keep();

 private:
  void create(const std::string& dir, const std::string& prefix, const std::string& suffix);
  void syncAndClose(std::int64_t expectedSize);
  [[noreturn]] void fail(const std::string& what) const;

  std::string target_, temp_;
  int fd_ = -1, slot_ = -1;
  std::uint64_t written_ = 0, dev_ = 0, ino_ = 0;
  bool done_ = false;
};

// Why `target` cannot be written as an AtomicFile writes it, or "" when it
// can: an existing directory, FIFO, socket or device (links followed) would
// be replaced by a regular file. "is a FIFO, not a file; ...", for
// messages that name the target before it. The one rule: AtomicFile checks
// it, and the CLI's and Python's output checks ask it before any work.
std::string unwritableTarget(const std::string& target);

// fsync of the directory holding `path`, so that a rename there survives a
// crash. Throws std::runtime_error.
void syncDirectoryOf(const std::string& path);

}  // namespace tg::io
