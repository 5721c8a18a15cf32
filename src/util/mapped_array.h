#pragma once
// An array of trivially copyable values in its own anonymous mapping, on
// transparent huge pages where the kernel allows: a std::vector that neither
// value-initialises what it reserves nor copies when it grows (mremap moves
// the pages). The guarded reader's parent receives arrays into extend()ed,
// untouched storage, so the one copy out of the child is the first write.
//
// Not a memfd shared with the child: the kernel gives shared memory no huge
// pages by default, and on the 2-core CI machine 88 MB of memfd cost 113 ms to
// fill and map, against 26 ms to fill huge pages and copy them once
// (measured with a standalone loop, minimum of 8).
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <span>
#include <type_traits>
#include <vector>

namespace tg::util {

// The untyped storage: `capacity()` bytes of a private anonymous mapping.
class MappedBytes {
 public:
  MappedBytes() = default;
  ~MappedBytes();
  MappedBytes(MappedBytes&& o) noexcept;
  MappedBytes& operator=(MappedBytes&& o) noexcept;
  MappedBytes(const MappedBytes&) = delete;
  MappedBytes& operator=(const MappedBytes&) = delete;

  void* data() const { return data_; }
  std::size_t capacity() const { return capacity_; }
  // At least `bytes` of capacity, keeping the contents. Throws std::bad_alloc
  // when the kernel refuses (the guard's RLIMIT_AS included).
  void grow(std::size_t bytes);

 private:
  void* data_ = nullptr;
  std::size_t capacity_ = 0;
};

template <class T>
class MappedArray {
  static_assert(std::is_trivially_copyable_v<T>);

 public:
  using value_type = T;
  using iterator = T*;
  using const_iterator = const T*;

  MappedArray() = default;
  MappedArray(std::initializer_list<T> v) { assign(v.begin(), v.size()); }
  explicit MappedArray(std::span<const T> v) { assign(v.data(), v.size()); }
  MappedArray(const MappedArray& o) { assign(o.data(), o.size()); }
  MappedArray& operator=(const MappedArray& o) {
    if (this != &o) {
      size_ = 0;
      assign(o.data(), o.size());
    }
    return *this;
  }
  MappedArray(MappedArray&& o) noexcept : mem_(std::move(o.mem_)), size_(o.size_) { o.size_ = 0; }
  MappedArray& operator=(MappedArray&& o) noexcept {
    mem_ = std::move(o.mem_);
    size_ = o.size_;
    o.size_ = 0;
    return *this;
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t capacity() const { return mem_.capacity() / sizeof(T); }
  T* data() { return static_cast<T*>(mem_.data()); }
  const T* data() const { return static_cast<const T*>(mem_.data()); }
  T& operator[](std::size_t i) { return data()[i]; }
  const T& operator[](std::size_t i) const { return data()[i]; }
  T* begin() { return data(); }
  T* end() { return data() + size_; }
  const T* begin() const { return data(); }
  const T* end() const { return data() + size_; }

  void reserve(std::size_t n) {
    if (n > capacity()) mem_.grow(n * sizeof(T));
  }
  // `n` more elements, uninitialised, at the end: one capacity check for a
  // whole record instead of one per value.
  T* extend(std::size_t n) {
    if (size_ + n > capacity()) mem_.grow(std::max(size_ + n, 2 * capacity()) * sizeof(T));
    T* p = data() + size_;
    size_ += n;
    return p;
  }
  void push_back(const T& v) { *extend(1) = v; }
  // Shrinking keeps the storage; growing value-initialises the new elements.
  void resize(std::size_t n) {
    if (n > size_) {
      const std::size_t add = n - size_;
      std::fill_n(extend(add), add, T{});
    }
    size_ = n;
  }
  void clear() { size_ = 0; }

  friend bool operator==(const MappedArray& a, const MappedArray& b) { return equal(a, b.data(), b.size()); }
  friend bool operator==(const MappedArray& a, const std::vector<T>& b) { return equal(a, b.data(), b.size()); }

 private:
  void assign(const T* p, std::size_t n) {
    if (n) std::memcpy(extend(n), p, n * sizeof(T));
  }
  static bool equal(const MappedArray& a, const T* p, std::size_t n) { return a.size_ == n && std::equal(p, p + n, a.data()); }
  MappedBytes mem_;
  std::size_t size_ = 0;
};

}  // namespace tg::util
