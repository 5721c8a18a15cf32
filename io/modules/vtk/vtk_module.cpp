// tensorglyph-vtk.so's entry point (io/core/format_modules.h).
#include "io/core/format_impl.h"

extern "C" __attribute__((visibility("default"))) const tg::io::VtkFormats* tg_vtk_formats() {
  namespace i = tg::io::impl;
  static constexpr tg::io::VtkFormats table{tg::io::VtkFormats::kVersion, i::readVtk, i::checkVtkLegacyHeader,
                                            i::checkVtkXmlHeader, i::readVtiScalar, i::readMesh, i::readPolylines, i::encodeVtk};
  return &table;
}
