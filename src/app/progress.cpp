#include "app/progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace tg::app {
namespace {

// A count in the units of `scale` (bytes: MB or GB; else k, M or G), and the suffix.
struct Scaled {
  double divisor;
  std::string suffix;
};
Scaled scaleFor(double v, std::string_view unit) {
  const std::string u(unit);
  if (unit == "bytes") return v >= 1e9 ? Scaled{1e9, " GB"} : Scaled{1e6, " MB"};
  if (v >= 1e9) return {1e9, " G " + u};
  if (v >= 1e6) return {1e6, " M " + u};
  if (v >= 1e4) return {1e3, " k " + u};
  return {1, " " + u};
}

std::string number(double v, const Scaled& s) {
  char buf[32];
  const double x = v / s.divisor;
  std::snprintf(buf, sizeof buf, x < 100 && x != std::floor(x) ? "%.1f" : "%.0f", x);
  return buf;
}

std::string duration(double s) {
  char buf[32];
  if (s < 1) return "<1 s";
  if (s < 60) std::snprintf(buf, sizeof buf, "%.0f s", s);
  else std::snprintf(buf, sizeof buf, "%.0f min %02.0f s", std::floor(s / 60), std::fmod(s, 60));
  return buf;
}

}  // namespace

std::string TerminalProgress::line(std::string_view stage, double done, double total, std::string_view unit,
                                   double seconds) {
  // The time so far: to a tenth of a second while it is short.
  auto soFar = [seconds] {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f s", seconds);
    return seconds < 10 ? std::string(buf) : duration(seconds);
  };
  std::string s(stage);
  s += ": ";
  const double rate = seconds > 0 && unit != util::kPassesUnit ? done / seconds : 0;
  if (total > 0) {
    char pct[16];
    std::snprintf(pct, sizeof pct, "%.0f%%", std::min(100.0, 100.0 * done / total));
    const Scaled t = scaleFor(total, unit);
    s += std::string(pct) + " (" + number(done, t) + " of " + number(total, t) + t.suffix + ")";
  } else if (done > 0) {
    const Scaled d = scaleFor(done, unit);
    s += number(done, d) + d.suffix;
  } else {
    return s + soFar();
  }
  // Nothing done yet, or work in uneven passes: a line that still moves.
  if (!(rate > 0)) return s + ", " + soFar();
  const Scaled r = scaleFor(rate, unit);
  s += ", " + number(rate, r) + r.suffix + "/s";
  if (total > done) s += ", " + duration((total - done) / rate) + " left";
  return s;
}

TerminalProgress::TerminalProgress(bool quiet, int fd) : fd_(fd) {
  if (!quiet && ::isatty(fd)) drawer_ = std::thread([this] { run(); });
}

void TerminalProgress::finish() {
  if (!drawer_.joinable()) return;
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  drawer_.join();
}

util::ProgressSink TerminalProgress::sink() {
  if (!drawer_.joinable()) return {};
  return [this](std::string_view stage, double done, double total, std::string_view unit) {
    update(stage, done, total, unit);
  };
}

void TerminalProgress::clearLocked() {
  if (!shown_) return;
  std::string blank(lastWidth_ + 2, ' ');
  blank.front() = blank.back() = '\r';
  if (::write(fd_, blank.data(), blank.size()) < 0) return;  // the terminal is gone: nothing to clear
  shown_ = false;
  lastWidth_ = 0;
}

void TerminalProgress::update(std::string_view stage, double done, double total, std::string_view unit) {
  const std::lock_guard lock(mutex_);
  hidden_ = stage.empty();
  if (hidden_) {
    clearLocked();
    return;
  }
  if (stage != stage_) {
    stage_ = stage;
    stageStart_ = Clock::now();
  }
  unit_ = unit;
  done_ = done;
  total_ = total;
}

void TerminalProgress::run() {
  std::unique_lock lock(mutex_);
  const auto started = Clock::now();
  for (;;) {
    wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stop_; });
    if (stop_) {
      clearLocked();
      return;
    }
    // Nothing before the delay: short work stays silent.
    if (stage_.empty() || hidden_ || (!shown_ && Clock::now() - started < kProgressDelay)) continue;
    const std::string l =
        line(stage_, done_, total_, unit_, std::chrono::duration<double>(Clock::now() - stageStart_).count());
    // Under the lock, so that a clear cannot fall between a line and the work's own message.
    std::string text = "\r";
    text.append(l).append(lastWidth_ > l.size() ? lastWidth_ - l.size() : 0, ' ');
    if (::write(fd_, text.data(), text.size()) < 0) continue;
    lastWidth_ = l.size();
    shown_ = true;
  }
}

}  // namespace tg::app
