#pragma once
// Linked programs kept between runs (GL_ARB_get_program_binary, core since
// GL 4.1): a program whose sources and driver match an entry is loaded from
// it instead of compiled and linked. Entries live in
// $XDG_CACHE_HOME/tensorglyph/programs (else ~/.cache/tensorglyph/programs),
// one file each, written whole by io/field/atomic_file.h. An entry is used only
// when its stored key (the driver's strings and every stage's composed
// source) equals the program's, its binary's checksum holds and the driver
// links it; anything else is ignored and the program compiled as without a
// cache.
//
// Off with TG_NO_PROGRAM_CACHE=1, and wherever the driver offers no binary
// format: Mesa offers one only while its own shader disk cache is on.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gl/loader.h"

namespace tg::gl {

class ProgramCache {
 public:
  // Reads the environment and the current context's driver strings.
  explicit ProgramCache(const Api& gl);
  bool enabled() const { return !dir_.empty(); }
  const std::string& directory() const { return dir_; }

  // The key of a program of `stages` (type, composed source): the driver's
  // strings first.
  std::string key(const std::vector<std::pair<GLenum, std::string_view>>& stages) const;
  // Links `program` (created, nothing attached) from the entry for `key`;
  // false when there is no usable entry, the program then unlinked.
  bool load(GLuint program, const std::string& key) const;
  // Stores the linked `program` under `key`. A cache: failures are ignored.
  void store(GLuint program, const std::string& key) const;

  // The entry format, apart from GL: bytes holding `binary` of driver format
  // `format` under `key`, and back (nullopt for anything malformed, with a
  // bad checksum or of another key).
  struct Binary {
    GLenum format = 0;
    std::vector<char> bytes;
  };
  static std::string encodeEntry(const std::string& key, const Binary& binary);
  static std::optional<Binary> decodeEntry(std::string_view entry, const std::string& key);

 private:
  std::string entryPath(const std::string& key) const;
  const Api& gl_;
  std::string dir_, driver_;
  std::vector<GLint> formats_;
};

}  // namespace tg::gl
