#include "gl/context.h"

namespace tg::gl {

void Context::loadEntryPoints() {
  api_ = loadApi([this](const char* name) { return procAddress(name); });
}

std::string Context::describe() const {
  auto str = [&](GLenum e) {
    const auto* s = reinterpret_cast<const char*>(api_.GetString(e));
    return std::string(s ? s : "?");
  };
  return str(GL_RENDERER) + " | " + str(GL_VERSION);
}

}  // namespace tg::gl
