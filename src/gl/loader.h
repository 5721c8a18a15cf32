#pragma once
// GL entry points as a per-context table. Each backend resolves them through
// its own GetProcAddress (OSMesa does not share glvnd's dispatch), so several
// backends can live in one process and nothing links libGL directly.
#include <functional>
#include <GL/glcorearb.h>

namespace tg::gl {

using ProcResolver = std::function<void*(const char*)>;

struct Api {
#define TG_GL(type, member, name) type member = nullptr;
#include "gl/gl_functions.inc"
#undef TG_GL
};

// Resolves every entry point; throws std::runtime_error naming the missing ones.
Api loadApi(const ProcResolver& resolve);

// Throws if glGetError reports an error, naming `where`.
void checkError(const Api& gl, const char* where);

}  // namespace tg::gl
