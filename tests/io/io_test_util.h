#pragma once
// Shared helpers of the reader tests: a scratch directory per test binary and
// the one-line error a read produces.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/core/readers.h"

namespace tg::test {

inline std::filesystem::path scratchDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("tg_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d;
}

// Writes `bytes` to `p` as they are (binary mode: no newline translation).
inline void writeFile(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

// The InputError message of reading `p`, or "" when it reads.
inline std::string readError(const std::filesystem::path& p, const io::ReadOptions& o = {}) {
  try {
    io::readTensorField(p.string(), o);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace tg::test
