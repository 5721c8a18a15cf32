// tensorglyph-nifti.so's entry point (io/core/format_modules.h).
#include "io/core/format_impl.h"

extern "C" __attribute__((visibility("default"))) const tg::io::NiftiFormats* tg_nifti_formats() {
  namespace i = tg::io::impl;
  static constexpr tg::io::NiftiFormats table{tg::io::NiftiFormats::kVersion, i::readNifti, i::readNiftiScalar};
  return &table;
}
