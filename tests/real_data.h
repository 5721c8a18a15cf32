#pragma once
// The datasets published by others live beside the checkout
// (../shared/data/real), as in CI. A clone without that directory skips the
// tests that read them and says where it looked; a file missing inside it
// still fails.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace tg::test {

inline std::string realData(const char* rel) { return std::string(TG_REAL_DATA_DIR) + "/" + rel; }

}  // namespace tg::test

#define TG_REQUIRE_REAL_DATA()                         \
  if (!std::filesystem::is_directory(TG_REAL_DATA_DIR)) \
  GTEST_SKIP() << "no published datasets at " TG_REAL_DATA_DIR
