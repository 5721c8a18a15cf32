#include "gl/loader.h"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace tg::gl {

Api loadApi(const ProcResolver& resolve) {
  Api api;
  std::string missing;
#define TG_GL(type, member, name)                               \
  api.member = reinterpret_cast<type>(resolve(#name));          \
  if (!api.member) missing += missing.empty() ? #name : ", " #name;
#include "gl/gl_functions.inc"
#undef TG_GL
  if (!missing.empty()) throw std::runtime_error("loadApi: missing GL entry points: " + missing);
  return api;
}

void checkError(const Api& gl, const char* where) {
  const GLenum e = gl.GetError();
  if (e != GL_NO_ERROR)
    throw std::runtime_error(std::string(where) + ": GL error 0x" + [&] {
      char buf[16];
      std::snprintf(buf, sizeof buf, "%04x", e);
      return std::string(buf);
    }());
}

}  // namespace tg::gl
