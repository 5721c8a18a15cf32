#pragma once
// Runs the real binary for the CLI tests and captures what it printed.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace tg::test {

struct CmdResult {
  int code;
  std::string out, err;
};

inline std::filesystem::path cliDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("tg_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d;
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

// `tensorglyph ARGS` (or another of the project's executables), with stdout
// and stderr kept in `scratch`.
inline CmdResult runBinary(const std::string& args, const std::filesystem::path& scratch,
                           const std::string& binary = TG_BINARY) {
  const auto out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  const std::string cmd = binary + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(cmd.c_str());
  return {WEXITSTATUS(status), slurp(out), slurp(err)};
}

// Runs `args` after removing `out`, and checks the bad-input contract: a
// non-zero exit, a message holding `what` in at most `maxLines` lines, and
// no output file.
inline void expectFailsCleanly(const std::string& args, const std::string& what, const std::filesystem::path& out,
                               const std::filesystem::path& scratch, long maxLines,
                               const std::string& binary = TG_BINARY) {
  std::filesystem::remove(out);
  const CmdResult r = runBinary(args, scratch, binary);
  EXPECT_NE(r.code, 0) << args;
  EXPECT_NE(r.err.find(what), std::string::npos) << args << " -> " << r.err;
  EXPECT_LE(std::count(r.err.begin(), r.err.end(), '\n'), maxLines) << args << " -> " << r.err;
  EXPECT_FALSE(std::filesystem::exists(out)) << args;
}

}  // namespace tg::test
