#pragma once
// The command line's progress line: stage, fraction, rate and time left on
// stderr, redrawn in place (\r) by a thread of its own at most 10 times a
// second, so that it also moves while one long call (a frame) blocks the
// work. Only when stderr is a terminal and --quiet was not given; work that
// ends within kProgressDelay shows nothing.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

#include "util/progress.h"

namespace tg::app {

inline constexpr std::chrono::milliseconds kProgressDelay{500};

class TerminalProgress {
 public:
  explicit TerminalProgress(bool quiet, int fd = 2);
  ~TerminalProgress() { finish(); }
  // Clears the line and stops drawing, before a command prints its results.
  void finish();
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  // Empty when nothing is shown, so that the work skips its reports.
  util::ProgressSink sink();

  // The text of one state, `seconds` into its stage:
  // "loading: 42% (120.5 of 286.1 MB), 95.3 MB/s, 2 s left"; without a
  // rate (nothing done yet, or util::kPassesUnit) the time so far:
  // "rendering: 33% (2 of 6 passes), 8.2 s".
  static std::string line(std::string_view stage, double done, double total, std::string_view unit, double seconds);

 private:
  using Clock = std::chrono::steady_clock;
  void update(std::string_view stage, double done, double total, std::string_view unit);
  void run();
  void clearLocked();

  int fd_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false, shown_ = false, hidden_ = false;
  std::string stage_, unit_;
  double done_ = 0, total_ = 0;
  Clock::time_point stageStart_{};
  std::size_t lastWidth_ = 0;
  std::thread drawer_;  // last: it starts once the state above exists
};

}  // namespace tg::app
