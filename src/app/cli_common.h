#pragma once
// Shared pieces of the subcommands: context creation and memory use; value
// parsing lives in cli_values.h, which needs no GL backend.
#include <memory>
#include <string>
#include <string_view>

#include "app/scale/cli_values.h"
#include "gl/context.h"

namespace tg::app {

// "osmesa", "egl", "glfw" or "auto" (a GPU through EGL if present, else OSMesa).
// checkBackend throws UsageError for any other name, so commands can reject
// it before loading anything.
inline constexpr const char* kBackendNames = "osmesa, egl, glfw or auto";
void checkBackend(std::string_view backend);
std::unique_ptr<gl::Context> createContext(std::string_view backend, int width, int height);

// Peak resident memory of this process so far, in bytes.
std::size_t peakRssBytes();

}  // namespace tg::app
