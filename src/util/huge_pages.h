#pragma once
// Reserving the big per-glyph and per-tensor arrays on transparent huge
// pages: a 100 MB array is 25,600 faults of 4 KiB, each zeroing its page in
// the kernel, against 50 of 2 MiB. Measured on load + eigen of 2M tensors
// (tests/bench/bench_load): 147 -> 133 ms for the records alone.
#include <cstdint>
#include <vector>

#include <sys/mman.h>

namespace tg::util {

// v.reserve(n), then MADV_HUGEPAGE on the whole 2 MiB pages inside the new
// storage. Only a hint: where the kernel has THP off, it changes nothing.
template <class T>
void reserveHuge(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  constexpr std::uintptr_t kHuge = std::uintptr_t(1) << 21;
  const auto a = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t lo = (a + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t hi = (a + n * sizeof(T)) & ~(kHuge - 1);
  if (hi > lo) ::madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
}

}  // namespace tg::util
