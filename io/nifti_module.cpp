// tensorglyph-nifti.so's entry point (io/format_modules.h).
#include "io/format_impl.h"

extern "C" __attribute__((visibility("default"))) const tg::io::NiftiFormats* tg_nifti_formats() {
  namespace i = tg::io::impl;
  static constexpr tg::io::NiftiFormats table{tg::io::NiftiFormats::kVersion, i::readNifti, i::readNiftiScalar};
  return &table;
}
