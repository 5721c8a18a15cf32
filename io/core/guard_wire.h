#pragma once
// The guarded reader's field on the wire (io/core/read_guard.h): PODs, strings and
// arrays in one fixed order over a socket pair. Arrays travel last and by
// address: the parent copies them straight out of the waiting child's memory
// (process_vm_readv) into untouched storage of its own, so the copy is the
// only pass over them; where the kernel refuses that (a seccomp profile, a
// ptrace policy), the child writes them into the socket instead. Open files
// travel as descriptors (SCM_RIGHTS), so that the parent reads the very file
// the child checked, whatever its name leads to by then.
#include <chrono>
#include <cstdint>
#include <deque>
#include <string>
#include <type_traits>
#include <vector>

#include <sys/types.h>

#include "util/mapped_array.h"
#include "util/unique_fd.h"

namespace tg::io {

// The child's end. Any failure to write means the parent is gone: _exit(3).
class WireOut {
 public:
  explicit WireOut(int fd) : fd_(fd) {}
  void bytes(const void* p, std::size_t n) { pending_.append(static_cast<const char*>(p), n); }
  template <class T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  void str(const std::string& s) {
    pod(std::uint64_t(s.size()));
    bytes(s.data(), s.size());
  }
  // An open file, passed with the first bytes sent; the parent takes it with
  // WireIn::takeFd, in the order passed. `fd` must stay open until finish().
  void passFd(int fd) { fds_.push_back(fd); }
  // Its length and address now; its bytes only if the parent asks (finish).
  template <class T>
  void array(const util::MappedArray<T>& v) {
    pod(std::uint64_t(v.size()));
    pod(std::uint64_t(reinterpret_cast<std::uintptr_t>(v.data())));
    // As WireIn::array: an empty array has nothing to fetch, so that both
    // ends agree on whether the child waits for a reply.
    if (!v.empty()) arrays_.push_back({v.data(), v.size() * sizeof(T)});
  }
  // Sends what is pending, waits for the parent's reply and, if it could not
  // read the arrays itself, writes them. The arrays must stay alive until then.
  void finish();

 private:
  void send(const void* p, std::size_t n);
  struct Span {
    const void* data;
    std::size_t bytes;
  };
  int fd_;
  std::string pending_;
  std::vector<Span> arrays_;
  std::vector<int> fds_;
};

// The parent's end: exactly the bytes asked for, before a deadline.
class WireIn {
 public:
  using Clock = std::chrono::steady_clock;
  WireIn(int fd, pid_t child, Clock::time_point deadline, std::uint64_t maxBytes)
      : fd_(fd), child_(child), deadline_(deadline), max_(maxBytes) {}
  void bytes(void* dst, std::size_t n);
  template <class T>
  T pod() {
    T v;
    bytes(&v, sizeof v);
    return v;
  }
  std::string str() {
    std::string s(count(1), '\0');
    bytes(s.data(), s.size());
    return s;
  }
  // Sizes `v` (untouched storage) and notes where the child holds it; the
  // bytes arrive in finish().
  template <class T>
  void array(util::MappedArray<T>& v) {
    const std::size_t n = count(sizeof(T));
    const auto at = pod<std::uint64_t>();
    v = {};
    if (n) arrays_.push_back({v.extend(n), n * sizeof(T), at});
  }
  // Fills every array noted, from the child's memory or from the socket.
  void finish();
  // The next descriptor the child passed (WireOut::passFd); throws
  // std::runtime_error where it passed none.
  util::UniqueFd takeFd();

 private:
  std::size_t count(std::size_t elementBytes);
  void wait() const;
  struct Pending {
    void* dst;
    std::size_t bytes;
    std::uint64_t childAddress;
  };
  int fd_;
  pid_t child_;
  Clock::time_point deadline_;
  std::uint64_t max_;
  std::uint64_t taken_ = 0;
  std::vector<Pending> arrays_;
  std::deque<util::UniqueFd> fds_;  // received, not yet taken
};

}  // namespace tg::io
