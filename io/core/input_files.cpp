#include "io/core/input_files.h"

#include <sys/stat.h>

#include <filesystem>

#include "io/core/format_table.h"

namespace tg::io {

std::vector<std::string> filesReadBy(const std::string& input) {
  std::vector<std::string> files{input};
  if (const InputFormatRow* row = inputFormatRowOf(input); row && row->dataFiles) {
    const auto data = row->dataFiles(input);
    files.insert(files.end(), data.begin(), data.end());
  }
  return files;
}

bool sameFile(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  const bool ea = stat(a.c_str(), &sa) == 0, eb = stat(b.c_str(), &sb) == 0;
  if (ea && eb) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  if (ea != eb) return false;
  std::error_code ec1, ec2;
  const auto ca = std::filesystem::weakly_canonical(a, ec1), cb = std::filesystem::weakly_canonical(b, ec2);
  return !ec1 && !ec2 && ca == cb;
}

}  // namespace tg::io
