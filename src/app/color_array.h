#pragma once
// Colour by a scalar given beside the tensors (render::ColorMode::Array):
// a VTK input's point array by name (read with the tensors,
// io::ReadOptions::colorArray), a scalar volume file on a volume input's
// grid, or in Python a NumPy array of one value per input tensor. The
// renderer takes them in the records' order (GlyphRenderer::setColorScalars),
// into a buffer of their own.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/core/selection.h"
#include "io/field/tensor_field.h"
#include "tensor/glyph.h"

namespace tg::app {

struct ColorValues {
  std::vector<float> byRecord;
  std::string name;  // the legend's title
};

// --color-array `name` for `set`, built from `field` (before its samples are
// released); none for an empty name. A scalar volume file is read into
// `volume` when that is empty, and taken from it when not: the whole field's
// range and the drawn glyphs' values come from one read (app::attachWholeField).
// UsageError naming --color-array and the file's point arrays when it has
// none of that name, or when `name` is no file for an input without point
// arrays; io::InputError for a volume file that is not on the tensors' grid.
std::optional<ColorValues> colorArrayValues(const std::string& name, const io::TensorField& field,
                                            const tensor::GlyphSet& set, std::optional<io::ScalarVolume>& volume);

// Values given one per input tensor (Python's color=array): `inputs` is the
// field's tensor count before any selection (TensorField::totalPoints).
// std::invalid_argument naming `option` for another count.
ColorValues colorValuesByInput(std::span<const float> byInput, std::size_t inputs, const tensor::GlyphSet& set,
                               const std::string& option);

}  // namespace tg::app
