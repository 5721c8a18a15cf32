// Tier 4: the progress line (app/progress.h) on the real binary: drawn in
// place on a terminal's stderr with stage, fraction, rate and time left;
// nothing on a pipe or with --quiet.
#include <filesystem>
#include <regex>
#include <string>

#include "cli/cli_run.h"
#include "cli/pty_run.h"

using namespace tg::test;

namespace {

// Large enough that each command runs past the line's half-second delay on
// a loaded 2-core machine (about 2 s of writing, 150 MB).
constexpr const char* kTensors = "6000000";

struct ProgressCli : ::testing::Test {
  std::filesystem::path dir = cliDir("progress");
  std::string field = (dir / "r.nhdr").string();
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::string synth(const std::string& extra) const {
    return std::string(TG_BINARY) + " synth random --n " + kTensors + " -o " + field + extra;
  }
};

// "\r" then "STAGE: P% (D of T ...), R .../s": a line redrawn in place.
bool hasLine(const std::string& err, const std::string& stage, const std::string& unit) {
  const std::regex line("\r" + stage + R"(: \d+% \([0-9.]+ of [0-9.]+ [kMG]? ?)" + unit + R"(\), [0-9.]+ [kMG]? ?)" + unit +
                        "/s");
  return std::regex_search(err, line);
}

}  // namespace

TEST_F(ProgressCli, SynthAndLoadDrawStageFractionRateAndTimeLeftOnATerminal) {
  const PtyResult s = runOnPty(synth(""));
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_TRUE(hasLine(s.err, "writing", "tensors")) << s.err;
  EXPECT_NE(s.err.find(" left"), std::string::npos) << s.err;
  EXPECT_EQ(s.err.find('\n'), std::string::npos) << "progress lines are redrawn, never scrolled: " << s.err;
  // The line is cleared at the end: the last thing written is a carriage return.
  ASSERT_FALSE(s.err.empty());
  EXPECT_EQ(s.err.back(), '\r');

  // info: the guarded child's read (bytes), then the eigen-decomposition.
  const PtyResult i = runOnPty(std::string(TG_BINARY) + " info " + field);
  ASSERT_EQ(i.code, 0) << i.err;
  EXPECT_TRUE(hasLine(i.err, "loading", "MB") || hasLine(i.err, "eigen", "tensors")) << i.err;
}

TEST_F(ProgressCli, NothingOnAPipeOrWithQuiet) {
  const CmdResult piped = runBinary("synth random --n " + std::string(kTensors) + " -o " + field, dir);
  ASSERT_EQ(piped.code, 0) << piped.err;
  EXPECT_EQ(piped.err, "");
  const PtyResult quiet = runOnPty(synth(" --quiet"));
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  const PtyResult info = runOnPty(std::string(TG_BINARY) + " info --quiet " + field);
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_EQ(info.err, "");
}
