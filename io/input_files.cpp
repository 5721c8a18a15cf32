#include "io/input_files.h"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

#include "io/readers.h"

namespace tg::io {

std::vector<std::string> filesReadBy(const std::string& input) {
  std::vector<std::string> files{input};
  std::string lower = input;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (lower.ends_with(".nrrd") || lower.ends_with(".nhdr")) {
    const auto data = nrrdDataFiles(input);
    files.insert(files.end(), data.begin(), data.end());
  }
  if (lower.ends_with(".mih")) {
    try {
      files.push_back(mifDataFile(input));
    } catch (const InputError&) {
      // A header the reader will refuse names no file to protect.
    }
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
