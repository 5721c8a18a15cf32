#pragma once
// How large a frame may be, known before any GL context exists, so that a
// size no framebuffer can hold is refused before anything is loaded.
#include <cstdint>

namespace tg::app {

// OpenGL 4.5 (what every backend here provides) guarantees MAX_TEXTURE_SIZE,
// MAX_RENDERBUFFER_SIZE and MAX_FRAMEBUFFER_WIDTH/HEIGHT of at least 16384.
// A larger side might fit some GPU, but nothing says so before a context.
inline constexpr int kMaxFrameSide = 16384;

// Bytes a width x height frame needs at once: the G-buffer
// (render::GBuffer::bytesFor) and the image read back and encoded (float
// RGBA, depth, normal and id, then 8-bit RGBA: 40 bytes per pixel).
std::uint64_t frameBytes(int width, int height);
// The budget for them: half of the machine's memory, at most 8 GiB.
std::uint64_t frameBudgetBytes();

// Throws UsageError "FLAG: W x H needs N GiB of frame buffers; ..." when
// frameBytes exceeds frameBudgetBytes.
void checkFrameSize(const char* flag, int width, int height);

}  // namespace tg::app
