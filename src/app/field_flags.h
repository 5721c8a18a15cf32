#pragma once
// The flags that choose what of a field is drawn and how big, shared by
// every subcommand that loads one (render, info, bench, view).
#include <optional>

#include <OpenImageIO/argparse.h>

#include "io/readers.h"
#include "tensor/glyph.h"

namespace tg::app {

struct FieldFlags {
  io::ReadOptions read;
  tensor::GlyphOptions glyph;
  std::optional<double> scale;
  std::optional<tensor::ScaleMode> scaleMode;

  // --array --layout --mask --mask-min --confidence-min --slice --stride
  // --roi --cl-min --cp-min --min-eigenvalue, and with `scaling` also
  // --scale and --scale-mode.
  void addTo(OIIO::ArgParse& ap, bool scaling);
  // Throws UsageError; called before anything is loaded.
  void validate() const;
  // World units per eigenvalue unit. --scale alone is absolute (as Teem's
  // -gsc); no flag at all means the spacing mode with factor 1.
  double scaleFor(const tensor::GlyphSet& set, double sampleSpacing) const;
};

// Prints a loaded field's warnings and skipped/masked counts on stderr,
// "tensorglyph COMMAND: FILE: ...", one line each.
void reportLoad(const io::TensorField& f, const char* command);

}  // namespace tg::app
