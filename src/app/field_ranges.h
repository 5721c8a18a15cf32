#pragma once
// Colour windows from the whole field: a slice, stride, region, mask or
// threshold chooses which glyphs are drawn, not what their colours mean, so
// that two slices of one field, or a slice beside the whole, share one
// window. FA thresholds are frame parameters and leave the uploaded glyphs
// whole; the load's selection does not, so a selected load reads the
// field again without it for its ranges (render::ColorRanges).
#include <functional>
#include <optional>

#include "app/render_options.h"
#include "io/field/tensor_field.h"
#include "render/color_scalar.h"

namespace tg::app {

// Whether `read` loads only part of the field (slice, stride, region, mask).
bool selectsPart(const io::ReadOptions& read);

// The ranges of the field that `load` reads with `o`'s read options less
// their selection; none when `o` selects nothing (the uploaded glyphs are
// the whole field then) or `load` is empty.
std::optional<render::ColorRanges> wholeFieldColorRanges(
    const RenderOptions& o, const std::function<io::TensorField(const io::ReadOptions&)>& load);

}  // namespace tg::app
