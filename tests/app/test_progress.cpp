// Tier 2: the progress line's text and its terminal: drawn only on a
// terminal, after the delay, at most 10 times a second, and cleared.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <pty.h>
#include <unistd.h>

#include <algorithm>
#include <string>
#include <thread>

#include "app/progress.h"

using tg::app::TerminalProgress;

TEST(ProgressLine, ShowsFractionRateAndTimeLeft) {
  // 30 of 120 frames in 10 s: 25%, 3 frames/s, 90 frames (30 s) to go.
  EXPECT_EQ(TerminalProgress::line("rendering", 30, 120, "frames", 10.0),
            "rendering: 25% (30 of 120 frames), 3 frames/s, 30 s left");
  EXPECT_EQ(TerminalProgress::line("loading", 120e6, 286.1e6, "bytes", 2.0),
            "loading: 42% (120 of 286 MB), 60 MB/s, 3 s left");
  EXPECT_EQ(TerminalProgress::line("eigen", 2.5e6, 20e6, "tensors", 125.0),
            "eigen: 12% (2.5 of 20 M tensors), 20 k tensors/s, 14 min 35 s left");
  // Unknown total: the count and rate, or the time so far.
  EXPECT_EQ(TerminalProgress::line("writing", 3e6, 0, "tensors", 1.5), "writing: 3 M tensors, 2 M tensors/s");
  EXPECT_EQ(TerminalProgress::line("generating", 0, 0, "", 12.2), "generating: 12 s");
  EXPECT_EQ(TerminalProgress::line("preparing", 0, 0, "", 0.64), "preparing: 0.6 s");
}

TEST(ProgressLine, PassesAndWorkNotYetBegunShowTheTimeSoFarNotARate) {
  // A frame's passes differ in cost: a rate of them would promise a time left
  // that the glyphs' pass alone outlasts.
  const std::string passes = TerminalProgress::line("rendering", 2, 6, tg::util::kPassesUnit, 8.24);
  EXPECT_EQ(passes, "rendering: 33% (2 of 6 passes), 8.2 s");
  EXPECT_EQ(passes.find("/s"), std::string::npos);
  EXPECT_EQ(passes.find("left"), std::string::npos);
  EXPECT_EQ(TerminalProgress::line("rendering", 5, 6, tg::util::kPassesUnit, 75.0),
            "rendering: 83% (5 of 6 passes), 1 min 15 s");
  // Nothing done yet of a known total: the line still moves.
  EXPECT_EQ(TerminalProgress::line("rendering", 0, 1, "frames", 12.0), "rendering: 0% (0 of 1 frames), 12 s");
  EXPECT_NE(TerminalProgress::line("rendering", 0, 1, "frames", 3.0), TerminalProgress::line("rendering", 0, 1, "frames", 4.0));
}

TEST(ProgressLine, DrawsOnATerminalOnlyAndClearsItself) {
  int pipeFds[2];
  ASSERT_EQ(::pipe(pipeFds), 0);
  {
    TerminalProgress onPipe(false, pipeFds[1]);
    EXPECT_FALSE(onPipe.sink()) << "a pipe gets no sink, so work skips its reports";
  }
  ::close(pipeFds[0]);
  ::close(pipeFds[1]);

  int master = -1, slave = -1;
  ASSERT_EQ(::openpty(&master, &slave, nullptr, nullptr, nullptr), 0);
  {
    TerminalProgress quiet(true, slave);
    EXPECT_FALSE(quiet.sink());
  }
  std::string text;
  {
    TerminalProgress p(false, slave);
    const auto sink = p.sink();
    ASSERT_TRUE(sink);
    sink("rendering", 1, 4, "frames");
    std::this_thread::sleep_for(std::chrono::milliseconds(1000));
    p.finish();
  }
  ::close(slave);
  for (char buf[4096];;) {
    const ssize_t n = ::read(master, buf, sizeof buf);
    if (n <= 0) break;
    text.append(buf, std::size_t(n));
  }
  ::close(master);
  EXPECT_NE(text.find("\rrendering: 25% (1 of 4 frames)"), std::string::npos) << text;
  // At most 10 lines a second, and none in the first half second.
  const auto lines = std::count(text.begin(), text.end(), '\r');
  EXPECT_GE(lines, 2);
  EXPECT_LE(lines, 8) << text;
  // Cleared: the last write is blanks between carriage returns.
  ASSERT_GE(text.size(), 2u);
  EXPECT_EQ(text.back(), '\r');
  const std::size_t prev = text.find_last_of('\r', text.size() - 2);
  ASSERT_NE(prev, std::string::npos);
  const std::string last = text.substr(prev + 1, text.size() - prev - 2);
  EXPECT_FALSE(last.empty());
  EXPECT_EQ(last.find_first_not_of(' '), std::string::npos) << text;
}
