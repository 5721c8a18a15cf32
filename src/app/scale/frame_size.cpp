#include "app/scale/frame_size.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "app/scale/cli_values.h"
#include "render/gbuffer.h"

namespace tg::app {
namespace {

constexpr std::uint64_t kGiB = 1ull << 30;
constexpr std::uint64_t kReadbackBytesPerPixel = 16 + 4 + 12 + 4 + 4;

std::string gib(std::uint64_t bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f GiB", double(bytes) / double(kGiB));
  return b;
}

}  // namespace

std::uint64_t frameBytes(int width, int height) {
  return render::GBuffer::bytesFor(width, height) + kReadbackBytesPerPixel * std::uint64_t(width) * std::uint64_t(height);
}

std::uint64_t frameBudgetBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  const std::uint64_t ram = pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : 16 * kGiB;
  return std::min(8 * kGiB, ram / 2);
}

void checkFrameSize(const char* flag, int width, int height) {
  const std::uint64_t need = frameBytes(width, height), budget = frameBudgetBytes();
  if (need > budget)
    throw UsageError(std::string(flag) + ": " + std::to_string(width) + "x" + std::to_string(height) + " needs " +
                     gib(need) + " of frame buffers (G-buffer and read-back image); the budget is " + gib(budget) +
                     " (half the memory, at most 8 GiB)");
}

}  // namespace tg::app
