#include "io/field/temp_registry.h"

#include <climits>
#include <csignal>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>

namespace tg::io {
namespace {

// This registry is the project's one piece of process-wide mutable state, on
// purpose: a signal handler receives nothing but the signal number, so the
// paths it must remove can only be found through static storage. It is kept
// to what a handler may touch (async-signal-safe): fixed arrays, lock-free
// atomics, unlink() and raise(); no allocation and no locks.
constexpr int kSlots = 32;
enum State : int { kFree, kFilling, kLive };
std::atomic<int> gState[kSlots];
char gPath[kSlots][PATH_MAX];
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void removeTempsAndDie(int sig) {
  for (int k = 0; k < kSlots; ++k)
    if (gState[k].load(std::memory_order_acquire) == kLive) unlink(gPath[k]);
  // The default action, so that the parent sees the signal as the cause.
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void installHandlers() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE}) {
    struct sigaction old {};
    sigaction(sig, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // e.g. under nohup: keep ignoring it
    struct sigaction sa {};
    sa.sa_handler = removeTempsAndDie;
    sigemptyset(&sa.sa_mask);
    for (int other : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE}) sigaddset(&sa.sa_mask, other);
    sigaction(sig, &sa, nullptr);
  }
}

}  // namespace

int registerTemp(const char* path) {
  static std::once_flag installed;
  std::call_once(installed, installHandlers);
  const std::size_t n = std::strlen(path);
  if (n >= PATH_MAX) throw std::runtime_error("registerTemp: " + std::string(path) + ": path too long");
  for (int k = 0; k < kSlots; ++k) {
    int expected = kFree;
    if (!gState[k].compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) continue;
    std::memcpy(gPath[k], path, n + 1);
    gState[k].store(kLive, std::memory_order_release);
    return k;
  }
  throw std::runtime_error("registerTemp: " + std::string(path) + ": more than 32 temporary files at once");
}

void releaseTemp(int slot) {
  if (slot >= 0 && slot < kSlots) gState[slot].store(kFree, std::memory_order_release);
}

}  // namespace tg::io
