#include "io/core/module_loader.h"

#include <dlfcn.h>
#include <link.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

namespace tg::io {
namespace {

// The main program's link map has an empty name (dladdr would give argv[0],
// maybe relative or a symbolic link elsewhere): /proc/self/exe names it.
std::string directoryOfThisCode() {
  Dl_info info{};
  link_map* map = nullptr;
  std::string file;
  if (dladdr1(reinterpret_cast<void*>(&directoryOfThisCode), &info, reinterpret_cast<void**>(&map),
              RTLD_DL_LINKMAP) &&
      map && map->l_name && map->l_name[0] == '/')
    file = map->l_name;
  if (file.empty()) {
    char buf[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) return ".";
    file.assign(buf, std::size_t(n));
  }
  const auto slash = file.find_last_of('/');
  return slash == 0 ? "/" : file.substr(0, slash);
}

}  // namespace

LoadedModule loadModule(const char* file, const char* entry, int version) {
  LoadedModule l;
  l.path = directoryOfThisCode() + "/" + file;
  struct stat st {};
  if (::stat(l.path.c_str(), &st) != 0) {
    l.error = "is missing";
    return l;
  }
  void* handle = dlopen(l.path.c_str(), RTLD_LAZY | RTLD_LOCAL);
  if (!handle) {
    const char* e = dlerror();
    l.error = std::string("did not load: ") + (e ? e : "unknown error");
    return l;
  }
  auto fn = reinterpret_cast<const void* (*)()>(dlsym(handle, entry));
  if (!fn) {
    l.error = std::string("has no entry point ") + entry;
    return l;
  }
  const void* table = fn();
  if (!table || *static_cast<const int*>(table) != version) {
    l.error = "is of another version";
    return l;
  }
  l.table = table;
  return l;
}

void throwModuleError(const std::string& who, const std::string& what, const char* library, const LoadedModule& m) {
  throw ModuleError(who + ": " + what + ": needs " + library + ", through the module " + m.path + ", which " +
                    m.error);
}

}  // namespace tg::io
