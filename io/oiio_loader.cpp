// Finds and loads the OpenImageIO module (io/oiio_module.h) beside the binary
// or shared object that holds this code: the tensorglyph executable, or later
// a Python extension, wherever it was installed.
#include <dlfcn.h>
#include <limits.h>
#include <unistd.h>

#include <stdexcept>
#include <string>

#include "io/oiio_module.h"

namespace tg::io {
namespace {

std::string directoryOfThisCode() {
  Dl_info info{};
  std::string file;
  if (dladdr(reinterpret_cast<void*>(&directoryOfThisCode), &info) && info.dli_fname &&
      std::string(info.dli_fname).find('/') != std::string::npos)
    file = info.dli_fname;
  if (file.empty()) {
    // The main program: dladdr gives its name as it was run, maybe bare.
    char buf[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) return ".";
    file.assign(buf, std::size_t(n));
  }
  const auto slash = file.find_last_of('/');
  return slash == 0 ? "/" : file.substr(0, slash);
}

struct Loaded {
  const OiioModule* module = nullptr;
  std::string path, error;
};

Loaded load() {
  Loaded l;
  l.path = directoryOfThisCode() + "/tensorglyph-oiio.so";
  void* handle = dlopen(l.path.c_str(), RTLD_LAZY | RTLD_LOCAL);
  if (!handle) {
    l.error = dlerror();
    return l;
  }
  auto entry = reinterpret_cast<const OiioModule* (*)()>(dlsym(handle, "tg_oiio_module"));
  if (!entry) {
    l.error = "no entry point tg_oiio_module";
    return l;
  }
  const OiioModule* m = entry();
  if (!m || m->version != OiioModule::kVersion) {
    l.error = "a module of another version";
    return l;
  }
  l.module = m;
  return l;
}

}  // namespace

const OiioModule& oiioModule(const std::string& who, const std::string& what) {
  // Loaded once per process; the handle stays open until exit.
  static const Loaded loaded = load();
  if (!loaded.module)
    throw std::runtime_error(who + ": " + what + ": needs OpenImageIO, through the module " + loaded.path +
                             ", which did not load: " + loaded.error);
  return *loaded.module;
}

}  // namespace tg::io
