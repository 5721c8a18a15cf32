#include "io/core/read_progress.h"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace tg::io {

std::optional<ReadPosition> childReadPosition(pid_t child) {
  const std::string base = "/proc/" + std::to_string(child);
  DIR* dir = ::opendir((base + "/fd").c_str());
  if (!dir) return std::nullopt;
  std::optional<ReadPosition> best;
  while (const dirent* e = ::readdir(dir)) {
    if (e->d_name[0] == '.') continue;
    struct stat st {};
    // stat follows the link to the open file itself: pipes and sockets are not regular.
    if (::stat((base + "/fd/" + e->d_name).c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    if (best && std::uint64_t(st.st_size) <= best->size) continue;
    FILE* info = std::fopen((base + "/fdinfo/" + e->d_name).c_str(), "r");
    if (!info) continue;
    unsigned long long pos = 0;
    const bool read = std::fscanf(info, "pos: %llu", &pos) == 1;
    std::fclose(info);
    if (read) best = ReadPosition{std::min<std::uint64_t>(pos, std::uint64_t(st.st_size)), std::uint64_t(st.st_size)};
  }
  ::closedir(dir);
  return best;
}

}  // namespace tg::io
