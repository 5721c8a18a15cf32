#include "io/core/module_loader.h"
#include "io/core/oiio_module.h"

namespace tg::io {

const OiioModule& oiioModule(const std::string& who, const std::string& what) {
  // Loaded once per process; the handle stays open until exit.
  static const LoadedModule loaded = loadModule("tensorglyph-oiio.so", "tg_oiio_module", OiioModule::kVersion);
  if (!loaded.table) throwModuleError(who, what, "OpenImageIO", loaded);
  return *static_cast<const OiioModule*>(loaded.table);
}

}  // namespace tg::io
