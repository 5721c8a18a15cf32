#pragma once
// The flags that choose what of a field is drawn and how big, shared by
// every subcommand that loads one (render, info, bench, view).
#include <optional>
#include <string>

#include "app/frame_check.h"
#include "app/scale/option_table.h"

#include "io/core/readers.h"
#include "tensor/glyph.h"
#include "tensor/glyph_scale.h"

namespace tg::app {

struct FieldFlags {
  io::ReadOptions read;
  tensor::GlyphOptions glyph;
  std::optional<double> scale;
  std::optional<tensor::ScaleMode> scaleMode;
  tensor::ScaleParams sizing;  // --magnitude, --lambda0, --clamp; mode and factor from the two above
  bool maskMinGiven = false;   // --mask-min needs --mask
  bool magnitudeGiven = false;      // --magnitude: a stress field's default does not apply
  bool sizesFromSelection = false;  // --sizes-from selection: sizes and colour ranges from the selection, not the whole field

  // --array --layout --frame --mask --mask-min --confidence-min --slice --stride
  // --roi --cl-min --cp-min --min-eigenvalue, and with `scaling` also
  // --scale, --scale-mode, --magnitude, --lambda0 and --clamp.
  void addTo(OptionTable& ap, bool scaling);
  // Throws UsageError; called before anything is loaded.
  void validate() const;
  // World units per eigenvalue unit. --scale alone is a factor on the
  // spacing mode's size; no flag at all means that mode with factor 1.
  double scaleFor(const tensor::GlyphSet& set, double sampleSpacing) const;
  // The whole choice: mode, factor, magnitude mapping and clamp.
  tensor::ScaleParams scaleParams() const;
};

// Before loading: UsageError naming the first option that `input`'s format
// (or the built-in scene, for "") has no use for.
void checkOptionsApply(const std::string& input, const io::ReadOptions& opt);
// After loading: UsageError for --confidence-min on tensors without a
// confidence; InputError naming the file when no tensor is left to draw
// (all skipped, masked or outside the selection).
void checkLoaded(const io::TensorField& f, const io::ReadOptions& opt);
// InputError when every glyph has zero size: nothing would be drawn.
void checkDrawable(const tensor::GlyphSet& g, const std::string& path);

// Prints a loaded field's warnings and skipped count on stderr,
// "tensorglyph COMMAND: FILE: ...", one line each, and the frame check's
// warning (app/frame_check.h) for a field read with `read`; returns the check.
FrameCheck reportLoad(const io::TensorField& f, const char* command, const io::ReadOptions& read);

}  // namespace tg::app
