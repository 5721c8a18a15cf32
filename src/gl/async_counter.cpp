#include "gl/async_counter.h"

namespace tg::gl {

AsyncCounter::AsyncCounter(const Api& gl) : gl_(gl) {
  gl.CreateBuffers(1, &copies_);
  gl.NamedBufferStorage(copies_, GLsizeiptr(slots_.size() * sizeof(GLuint)), nullptr, 0);
}

AsyncCounter::~AsyncCounter() {
  for (Slot& s : slots_)
    if (s.fence) gl_.DeleteSync(s.fence);
  gl_.DeleteBuffers(1, &copies_);
}

AsyncCounter::Slot& AsyncCounter::claim() {
  Slot& s = slots_[next_ % slots_.size()];
  if (s.fence) gl_.DeleteSync(s.fence);
  s = Slot{nullptr, 0, next_++};
  return s;
}

void AsyncCounter::request(GLuint buffer) {
  Slot& s = claim();
  const auto at = GLintptr(std::size_t(&s - slots_.data()) * sizeof(GLuint));
  gl_.CopyNamedBufferSubData(buffer, copies_, 0, at, sizeof(GLuint));
  s.fence = gl_.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

void AsyncCounter::requestKnown(std::uint64_t value) { claim().value = value; }

std::optional<std::uint64_t> AsyncCounter::latest() {
  for (std::size_t k = 0; k < slots_.size(); ++k) {
    Slot& s = slots_[k];
    if (s.sequence <= latestSequence_) continue;
    if (s.fence) {
      // Timeout 0: only asks whether the copy has run.
      const GLenum st = gl_.ClientWaitSync(s.fence, 0, 0);
      if (st != GL_ALREADY_SIGNALED && st != GL_CONDITION_SATISFIED) continue;
      GLuint v = 0;
      gl_.GetNamedBufferSubData(copies_, GLintptr(k * sizeof(GLuint)), sizeof(GLuint), &v);
      gl_.DeleteSync(s.fence);
      s.fence = nullptr;
      s.value = v;
    }
    latestSequence_ = s.sequence;
    latest_ = s.value;
  }
  return latest_;
}

}  // namespace tg::gl
