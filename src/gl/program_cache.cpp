#include "gl/program_cache.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>

#include "io/field/atomic_file.h"

namespace tg::gl {
namespace {

constexpr char kMagic[8] = {'T', 'G', 'P', 'R', 'O', 'G', '1', '\n'};
// A linked program's binary is tens to hundreds of KiB; a bigger file is not one of ours.
constexpr std::uint64_t kMaxEntryBytes = std::uint64_t(64) << 20;

struct Header {
  char magic[8];
  std::uint32_t format, zero;
  std::uint64_t keyBytes, binaryBytes;
  std::uint64_t binaryHash;  // hashOf; the key is compared whole
};
static_assert(sizeof(Header) == 40);

// Of the binary and its format: a flipped bit in either is caught.
std::uint64_t hashOf(GLenum format, const char* bytes, std::size_t n) {
  return std::uint64_t(std::hash<std::string_view>{}(std::string_view(bytes, n))) ^
         (std::uint64_t(format) * 0x9E3779B97F4A7C15u);
}

std::string driverString(const Api& gl, GLenum name) {
  const auto* s = reinterpret_cast<const char*>(gl.GetString(name));
  return s ? s : "";
}

// $XDG_CACHE_HOME/tensorglyph/programs, else $HOME/.cache/...; relative
// settings are ignored, as the XDG base directory specification says.
std::string cacheDirectory() {
  if (const char* off = std::getenv("TG_NO_PROGRAM_CACHE"); off && std::string_view(off) == "1") return "";
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && xdg[0] == '/') return std::string(xdg) + "/tensorglyph/programs";
  const char* home = std::getenv("HOME");
  if (home && home[0] == '/') return std::string(home) + "/.cache/tensorglyph/programs";
  return "";
}

}  // namespace

ProgramCache::ProgramCache(const Api& gl) : gl_(gl) {
  std::string dir = cacheDirectory();
  if (dir.empty()) return;
  GLint n = 0;
  gl.GetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &n);
  if (n <= 0) return;
  formats_.resize(std::size_t(n));
  gl.GetIntegerv(GL_PROGRAM_BINARY_FORMATS, formats_.data());
  for (GLenum s : {GL_VENDOR, GL_RENDERER, GL_VERSION, GL_SHADING_LANGUAGE_VERSION})
    driver_ += driverString(gl, s) + '\n';
  dir_ = std::move(dir);
}

std::string ProgramCache::key(const std::vector<std::pair<GLenum, std::string_view>>& stages) const {
  std::string k = driver_;
  for (const auto& [stage, text] : stages)
    k.append(std::to_string(stage)).append(" ").append(std::to_string(text.size())).append("\n").append(text);
  return k;
}

std::string ProgramCache::entryPath(const std::string& key) const {
  char name[32];
  std::snprintf(name, sizeof name, "%016zx.bin", std::hash<std::string>{}(key));
  return dir_ + "/" + name;
}

std::string ProgramCache::encodeEntry(const std::string& key, const Binary& binary) {
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.format = binary.format;
  h.keyBytes = key.size();
  h.binaryBytes = binary.bytes.size();
  h.binaryHash = hashOf(binary.format, binary.bytes.data(), binary.bytes.size());
  std::string out(reinterpret_cast<const char*>(&h), sizeof h);
  out.append(key).append(binary.bytes.data(), binary.bytes.size());
  return out;
}

std::optional<ProgramCache::Binary> ProgramCache::decodeEntry(std::string_view entry, const std::string& key) {
  Header h{};
  if (entry.size() < sizeof h) return std::nullopt;
  std::memcpy(&h, entry.data(), sizeof h);
  // Sizes compared one at a time: their sum could wrap.
  const std::uint64_t rest = entry.size() - sizeof h;
  if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0 || h.zero != 0 || h.keyBytes != key.size() ||
      h.keyBytes > rest || h.binaryBytes != rest - h.keyBytes || h.binaryBytes == 0)
    return std::nullopt;
  const std::string_view storedKey = entry.substr(sizeof h, std::size_t(h.keyBytes));
  const char* bytes = entry.data() + sizeof h + h.keyBytes;
  if (storedKey != key || hashOf(GLenum(h.format), bytes, std::size_t(h.binaryBytes)) != h.binaryHash)
    return std::nullopt;
  return Binary{GLenum(h.format), std::vector<char>(bytes, bytes + h.binaryBytes)};
}

bool ProgramCache::load(GLuint program, const std::string& key) const {
  if (!enabled()) return false;
  // Non-blocking, regular files only: a FIFO planted at the name must not hang the program.
  const int fd = ::open(entryPath(key).c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st {};
  std::string entry;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 && std::uint64_t(st.st_size) <= kMaxEntryBytes) {
    entry.resize(std::size_t(st.st_size));
    std::size_t got = 0;
    while (got < entry.size()) {
      const ssize_t n = ::read(fd, entry.data() + got, entry.size() - got);
      if (n <= 0) break;  // a short entry fails to decode
      got += std::size_t(n);
    }
    entry.resize(got);
  }
  ::close(fd);
  const std::optional<Binary> b = decodeEntry(entry, key);
  if (!b || std::find(formats_.begin(), formats_.end(), GLint(b->format)) == formats_.end()) return false;
  gl_.ProgramBinary(program, b->format, b->bytes.data(), GLsizei(b->bytes.size()));
  // A rejected binary leaves the program unlinked; any error it raised must
  // not surface in a later check.
  for (int k = 0; k < 8 && gl_.GetError() != GL_NO_ERROR; ++k) {
  }
  GLint ok = 0;
  gl_.GetProgramiv(program, GL_LINK_STATUS, &ok);
  return ok == GL_TRUE;
}

void ProgramCache::store(GLuint program, const std::string& key) const {
  if (!enabled()) return;
  GLint length = 0;
  gl_.GetProgramiv(program, GL_PROGRAM_BINARY_LENGTH, &length);
  if (length <= 0 || std::uint64_t(length) > kMaxEntryBytes) return;
  Binary b;
  b.bytes.resize(std::size_t(length));
  GLsizei got = 0;
  gl_.GetProgramBinary(program, length, &got, &b.format, b.bytes.data());
  if (gl_.GetError() != GL_NO_ERROR || got <= 0) return;
  b.bytes.resize(std::size_t(got));
  const std::string entry = encodeEntry(key, b);
  try {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec) return;
    // The cache's own directory: a FIFO or device planted at an entry is
    // removed (the link, not its target), which AtomicFile would refuse.
    if (!io::unwritableTarget(entryPath(key)).empty()) std::filesystem::remove(entryPath(key), ec);
    io::AtomicFile out(entryPath(key));
    out.write(entry.data(), entry.size());
    out.commit(std::int64_t(entry.size()));
  } catch (const std::exception&) {
    // An unwritable or full cache directory: the program is linked all the same.
  }
}

}  // namespace tg::gl
