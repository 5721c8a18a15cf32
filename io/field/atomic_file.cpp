#include "io/field/atomic_file.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "io/field/temp_registry.h"

namespace tg::io {
namespace {

constexpr std::size_t kRandomChars = 12;

std::string randomName() {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  unsigned char bytes[kRandomChars];
  std::size_t got = 0;
  while (got < sizeof bytes) {
    const ssize_t r = getrandom(bytes + got, sizeof bytes - got, 0);
    if (r < 0 && errno != EINTR) throw std::runtime_error(std::string("getrandom: ") + std::strerror(errno));
    if (r > 0) got += std::size_t(r);
  }
  std::string s;
  for (unsigned char b : bytes) s += kAlphabet[b % 62];
  return s;
}

std::filesystem::path dirOf(const std::string& target) {
  const std::filesystem::path p(target);
  return p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
}

}  // namespace

// A new file at dir/prefix RANDOM suffix. O_EXCL never opens an existing
// name, and with O_CREAT it refuses a symbolic link there, dangling or not;
// O_NOFOLLOW says so twice. Mode 0666 lets the kernel apply the umask (and a
// default ACL), so the committed file has the permissions any new file would
// have, unlike mkstemp's 0600. The name is registered before the file exists,
// so that no signal can come between the two and leave it behind.
// A prefix too long for the file system's name limit (NAME_MAX, 255 bytes on
// most) is cut, between UTF-8 characters, so that a target named up to the
// limit is still written: its temporary name is 18 bytes longer.
void AtomicFile::create(const std::string& dir, const std::string& prefix, const std::string& suffix) {
  const std::filesystem::path d = dir.empty() ? std::filesystem::path(".") : std::filesystem::path(dir);
  const long limit = pathconf(d.c_str(), _PC_NAME_MAX);
  const std::size_t nameMax = limit > 0 ? std::size_t(limit) : 255, fixed = kRandomChars + suffix.size();
  std::string head = prefix;
  if (head.size() + fixed > nameMax && fixed + 2 <= nameMax) {
    std::size_t n = nameMax - fixed;
    while (n > 1 && (static_cast<unsigned char>(head[n]) & 0xC0) == 0x80) --n;
    head.resize(n);
  }
  for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
    temp_ = (d / (head + randomName() + suffix)).string();
    slot_ = registerTemp(temp_.c_str());
    fd_ = open(temp_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ >= 0) break;
    const int err = errno;
    releaseTemp(slot_);
    slot_ = -1;
    if (err != EEXIST) {
      temp_.clear();
      fail(std::string("cannot create a file in its directory: ") + std::strerror(err));
    }
  }
  if (fd_ < 0) {
    temp_.clear();
    fail("cannot create a file in its directory: 100 random names taken");
  }
  struct stat st {};
  fstat(fd_, &st);
  dev_ = st.st_dev;
  ino_ = st.st_ino;
}

std::string unwritableTarget(const std::string& target) {
  struct stat st {};
  if (stat(target.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return "";
  if (S_ISDIR(st.st_mode)) return "is a directory";
  return std::string("is ") + (S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISSOCK(st.st_mode) ? "a socket" : "a device") +
         ", not a file; outputs are written to a file and renamed into place";
}

AtomicFile::AtomicFile(const std::string& target) : target_(target) {
  const std::filesystem::path p(target);
  if (!p.has_filename()) fail("not a file name");
  if (const std::string why = unwritableTarget(target); !why.empty()) fail(why);
  // Appended piece by piece: GCC 12's -Wrestrict misfires on "." + string.
  std::string prefix(1, '.'), suffix = ".tmp";
  prefix.append(p.stem().string()).append("-");
  suffix.append(p.extension().string());
  create(dirOf(target).string(), prefix, suffix);
}

AtomicFile::AtomicFile(UniqueName, const std::string& dir, const std::string& stem, const std::string& ext)
    : target_((std::filesystem::path(dir) / (stem + ext)).string()) {
  create(dir, stem + ".", ext);
  target_ = temp_;
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) close(fd_);
  if (!done_ && !temp_.empty()) unlink(temp_.c_str());
  releaseTemp(slot_);
}

void AtomicFile::fail(const std::string& what) const {
  throw std::runtime_error("AtomicFile: " + target_ + ": " + what);
}

void AtomicFile::write(const void* data, std::size_t n) {
  const auto* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd_, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) fail(std::string("write failed: ") + (w < 0 ? std::strerror(errno) : "no progress"));
    p += w;
    n -= std::size_t(w);
    written_ += std::uint64_t(w);
  }
}

void AtomicFile::syncAndClose(std::int64_t expectedSize) {
  // A writer that reopened the path by name must have written this very file.
  struct stat now {};
  if (lstat(temp_.c_str(), &now) != 0 || now.st_dev != dev_ || now.st_ino != ino_ || !S_ISREG(now.st_mode))
    fail("the temporary file " + temp_ + " was replaced while being written");
  if (expectedSize >= 0 && now.st_size != expectedSize)
    fail("wrote " + std::to_string(now.st_size) + " bytes, not " + std::to_string(expectedSize) + " (disk full?)");
  // Disk full often shows only here: delayed allocation, or NFS at close.
  if (fsync(fd_) != 0) fail(std::string("fsync failed: ") + std::strerror(errno));
  const int fd = fd_;
  fd_ = -1;
  if (close(fd) != 0) fail(std::string("close failed: ") + std::strerror(errno));
}

void AtomicFile::commit(std::int64_t expectedSize) {
  syncAndClose(expectedSize);
  // A FIFO or device made at the target while this file was written.
  if (const std::string why = unwritableTarget(target_); !why.empty()) fail(why);
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) fail(std::string("rename failed: ") + std::strerror(errno));
  done_ = true;
  releaseTemp(slot_);
  slot_ = -1;
  syncDirectoryOf(target_);
}

void AtomicFile::commitExchange(std::int64_t expectedSize,
                                const std::function<void(const std::string& displaced)>& displaced) {
  syncAndClose(expectedSize);
  for (;;) {
    if (renameat2(AT_FDCWD, temp_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
      // The temporary name now holds the displaced target; still registered,
      // so a signal removes it as well.
      syncDirectoryOf(target_);
      displaced(temp_);
      unlink(temp_.c_str());
      break;
    }
    if (errno == ENOENT) {
      // No target yet: create it, unless another writer just did (then exchange).
      if (renameat2(AT_FDCWD, temp_.c_str(), AT_FDCWD, target_.c_str(), RENAME_NOREPLACE) == 0) break;
      if (errno == EEXIST) continue;
    }
    if (errno != EINVAL && errno != ENOSYS) fail(std::string("rename failed: ") + std::strerror(errno));
    // A file system without exchange: a plain rename; under a race the
    // displaced header's data may then stay behind, never a wrong pairing.
    if (std::rename(temp_.c_str(), target_.c_str()) != 0) fail(std::string("rename failed: ") + std::strerror(errno));
    break;
  }
  done_ = true;
  releaseTemp(slot_);
  slot_ = -1;
  syncDirectoryOf(target_);
}

void AtomicFile::keep() {
  syncAndClose(-1);
  done_ = true;
  releaseTemp(slot_);
  slot_ = -1;
  syncDirectoryOf(target_);
}

void syncDirectoryOf(const std::string& path) {
  const std::string dir = dirOf(path).string();
  const int fd = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("syncDirectoryOf: " + dir + ": " + std::strerror(errno));
  const int r = fsync(fd);
  const int err = errno;
  close(fd);
  // Some file systems cannot sync a directory (EINVAL); their renames are as durable as they get.
  if (r != 0 && err != EINVAL) throw std::runtime_error("syncDirectoryOf: " + dir + ": " + std::strerror(err));
}

}  // namespace tg::io
