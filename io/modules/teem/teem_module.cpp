// tensorglyph-teem.so's entry point (io/core/format_modules.h).
#include "io/core/format_impl.h"

extern "C" __attribute__((visibility("default"))) const tg::io::TeemFormats* tg_teem_formats() {
  namespace i = tg::io::impl;
  static constexpr tg::io::TeemFormats table{tg::io::TeemFormats::kVersion, i::readNrrd, i::readNrrdScalar,
                                             i::nrrdDataFiles, i::writeNrrd, i::writeRawTensorHeader};
  return &table;
}
