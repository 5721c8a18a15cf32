#pragma once
// Finds and loads the program's modules (tensorglyph-oiio.so,
// tensorglyph-vtk.so, ...) beside the binary or shared object that holds this
// code: the tensorglyph executable, or a Python extension, wherever it was
// installed. Each module exports one C function returning a table of entry
// points whose first member is its version (io/core/format_modules.h,
// io/core/oiio_module.h).
#include <stdexcept>
#include <string>

namespace tg::io {

// A module that could not be loaded. Carried verbatim out of the guarded
// reader's child (io/core/read_guard.h): it names the module, not a corrupt file.
class ModuleError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LoadedModule {
  const void* table = nullptr;  // null: see error
  std::string path, error;
};

// Opens `file` from the modules' directory, calls `entry` and checks that the
// table's leading int is `version`. Never throws; the handle stays open.
LoadedModule loadModule(const char* file, const char* entry, int version);

// "<who>: <what>: needs <library>, through the module <path>, which <error>".
[[noreturn]] void throwModuleError(const std::string& who, const std::string& what, const char* library,
                                   const LoadedModule& m);

}  // namespace tg::io
