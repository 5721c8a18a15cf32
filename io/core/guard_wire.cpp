#include "io/core/guard_wire.h"

#include <poll.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace tg::io {
namespace {

// At most this many descriptors ride on one message.
constexpr std::size_t kMaxFds = 4;

// The parent's reply once it has the arrays' addresses.
constexpr char kCopied = 'D';     // it copied them itself: exit
constexpr char kWriteThem = 'W';  // it cannot: write them into the socket

}  // namespace

void WireOut::send(const void* p, std::size_t n) {
  const char* c = static_cast<const char*>(p);
  while (n > 0) {
    const ssize_t w = ::write(fd_, c, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) _exit(3);
    c += w;
    n -= std::size_t(w);
  }
}

void WireOut::finish() {
  if (!fds_.empty()) {
    // The descriptors ride on the first byte; the rest follows as usual.
    if (pending_.empty() || fds_.size() > kMaxFds) _exit(3);
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int) * kMaxFds)] = {};
    iovec first{pending_.data(), 1};
    msghdr m{};
    m.msg_iov = &first;
    m.msg_iovlen = 1;
    m.msg_control = control;
    m.msg_controllen = CMSG_SPACE(sizeof(int) * fds_.size());
    cmsghdr* c = CMSG_FIRSTHDR(&m);
    c->cmsg_level = SOL_SOCKET;
    c->cmsg_type = SCM_RIGHTS;
    c->cmsg_len = CMSG_LEN(sizeof(int) * fds_.size());
    std::memcpy(CMSG_DATA(c), fds_.data(), sizeof(int) * fds_.size());
    ssize_t w;
    while ((w = ::sendmsg(fd_, &m, MSG_NOSIGNAL)) < 0 && errno == EINTR) {}
    if (w != 1) _exit(3);
    pending_.erase(0, 1);
    fds_.clear();
  }
  send(pending_.data(), pending_.size());
  pending_.clear();
  if (arrays_.empty()) return;
  char reply = 0;
  ssize_t got;
  while ((got = ::read(fd_, &reply, 1)) < 0 && errno == EINTR) {}
  if (got != 1) _exit(3);
  if (reply == kWriteThem)
    for (const Span& a : arrays_) send(a.data, a.bytes);
}

void WireIn::wait() const {
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - Clock::now()).count();
    if (left <= 0) throw std::runtime_error("the reader's result did not arrive in time");
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, int(std::min<long long>(left, 1000))) > 0) return;
  }
}

void WireIn::bytes(void* dst, std::size_t n) {
  char* c = static_cast<char*>(dst);
  while (n > 0) {
    wait();
    // recvmsg, so that descriptors passed with these bytes are kept.
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int) * kMaxFds)];
    iovec io{c, n};
    msghdr m{};
    m.msg_iov = &io;
    m.msg_iovlen = 1;
    m.msg_control = control;
    m.msg_controllen = sizeof control;
    const ssize_t got = ::recvmsg(fd_, &m, MSG_CMSG_CLOEXEC);
    if (got < 0 && errno == EINTR) continue;
    for (cmsghdr* h = got > 0 ? CMSG_FIRSTHDR(&m) : nullptr; h; h = CMSG_NXTHDR(&m, h))
      if (h->cmsg_level == SOL_SOCKET && h->cmsg_type == SCM_RIGHTS)
        for (std::size_t k = 0; k < (h->cmsg_len - CMSG_LEN(0)) / sizeof(int); ++k) {
          int fd;
          std::memcpy(&fd, CMSG_DATA(h) + k * sizeof(int), sizeof fd);
          fds_.emplace_back(fd);
        }
    if (got > 0 && (m.msg_flags & MSG_CTRUNC)) throw std::runtime_error("the reader's result is malformed");
    if (got <= 0) throw std::runtime_error("the reader's result is short");
    c += got;
    n -= std::size_t(got);
  }
}

util::UniqueFd WireIn::takeFd() {
  if (fds_.empty()) throw std::runtime_error("the reader's result is malformed (a file it names did not arrive)");
  util::UniqueFd fd = std::move(fds_.front());
  fds_.pop_front();
  return fd;
}

std::size_t WireIn::count(std::size_t elementBytes) {
  const auto n = pod<std::uint64_t>();
  // All strings and arrays together stay within what the child could hold.
  if (n > max_ / elementBytes || n * elementBytes > max_ - std::min(max_, taken_))
    throw std::runtime_error("the reader's result is malformed");
  taken_ += n * elementBytes;
  return std::size_t(n);
}

void WireIn::finish() {
  if (arrays_.empty()) return;
  bool copied = true;
  for (const Pending& a : arrays_) {
    for (std::size_t done = 0; done < a.bytes;) {
      iovec local{static_cast<char*>(a.dst) + done, a.bytes - done};
      iovec remote{reinterpret_cast<void*>(std::uintptr_t(a.childAddress + done)), a.bytes - done};
      const ssize_t got = ::process_vm_readv(child_, &local, 1, &remote, 1, 0);
      if (got > 0) {
        done += std::size_t(got);
        continue;
      }
      if (got < 0 && errno == EINTR) continue;
      // Refused by policy before any array was read: the socket instead.
      if (got < 0 && (errno == EPERM || errno == ENOSYS || errno == EACCES) && &a == &arrays_.front() && done == 0) {
        copied = false;
        break;
      }
      throw std::runtime_error("the reader's result is malformed (its arrays cannot be read)");
    }
    if (!copied) break;
  }
  const char reply = copied ? kCopied : kWriteThem;
  if (::write(fd_, &reply, 1) != 1) throw std::runtime_error("the reader ended before its result was read");
  if (!copied)
    for (const Pending& a : arrays_) bytes(a.dst, a.bytes);
}

}  // namespace tg::io
