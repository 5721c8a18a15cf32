#pragma once
// Reads a GPU-written counter without stalling the frame: each request copies
// the counter aside behind a fence, and a poll returns the newest copy whose
// fence has passed. A viewer's status line then trails the GPU by a frame or
// two instead of waiting for it every frame.
#include <array>
#include <cstdint>
#include <optional>

#include "gl/loader.h"

namespace tg::gl {

class AsyncCounter {
 public:
  explicit AsyncCounter(const Api& gl);
  ~AsyncCounter();
  AsyncCounter(const AsyncCounter&) = delete;
  AsyncCounter& operator=(const AsyncCounter&) = delete;

  // Copies the GLuint at `buffer` (offset 0) once the commands issued so far
  // have run. With more requests in flight than slots, the oldest is dropped.
  void request(GLuint buffer);
  // A value known on the CPU, delivered in request order all the same.
  void requestKnown(std::uint64_t value);
  // The newest finished value, never waiting; empty until one has finished.
  std::optional<std::uint64_t> latest();

 private:
  struct Slot {
    GLsync fence = nullptr;
    std::uint64_t value = 0;
    std::uint64_t sequence = 0;  // 0: empty
  };
  Slot& claim();
  const Api& gl_;
  GLuint copies_ = 0;  // one GLuint per slot
  std::array<Slot, 4> slots_;
  std::uint64_t next_ = 1, latestSequence_ = 0;
  std::optional<std::uint64_t> latest_;
};

}  // namespace tg::gl
