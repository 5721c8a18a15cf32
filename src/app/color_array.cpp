#include "app/color_array.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "app/scale/cli_values.h"
#include "io/core/selection.h"
#include "render/color_scalar.h"

namespace tg::app {

std::optional<ColorValues> colorArrayValues(const std::string& name, const io::TensorField& field,
                                            const tensor::GlyphSet& set, std::optional<io::ScalarVolume>& volume) {
  if (name.empty()) return std::nullopt;
  if (!field.pointArrays.empty())
    throw UsageError("--color-array: " + field.path + " has no point array named \"" + name + "\"; its point arrays: " +
                     field.pointArrays);
  std::vector<float> byInput;
  if (!field.colorArrayName.empty()) {
    // One value per kept tensor, beside the ids: by input index, NaN for the others.
    std::size_t inputs = field.totalPoints;
    for (std::size_t k = 0; k < field.ids.size(); ++k) inputs = std::max(inputs, std::size_t(field.ids[k]) + 1);
    byInput.assign(inputs, std::numeric_limits<float>::quiet_NaN());
    for (std::size_t k = 0; k < field.ids.size() && k < field.colorValues.size(); ++k)
      byInput[field.ids[k]] = field.colorValues[k];
    return ColorValues{render::scalarsByRecord(std::span(set.glyphs.data(), set.glyphs.size()), byInput),
                       field.colorArrayName};
  }
  if (!field.grid)
    throw UsageError("--color-array: " + field.path + " has no point arrays; a VTK input names one, a volume input "
                     "gives a scalar volume file on its grid");
  if (!volume) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(name, ec))
      throw UsageError("--color-array: \"" + name + "\" is no file; for this volume input give a scalar volume on " +
                       "its grid (a VTK input names a point array)");
    volume = io::readScalarVolume(name, field.grid->dims);
  }
  return ColorValues{render::scalarsByRecord(std::span(set.glyphs.data(), set.glyphs.size()), volume->values),
                     std::filesystem::path(name).filename().string()};
}

ColorValues colorValuesByInput(std::span<const float> byInput, std::size_t inputs, const tensor::GlyphSet& set,
                               const std::string& option) {
  if (byInput.size() != inputs)
    throw std::invalid_argument(option + ": " + std::to_string(byInput.size()) + " values for " +
                                std::to_string(inputs) + " tensors; give one value per tensor");
  return ColorValues{render::scalarsByRecord(std::span(set.glyphs.data(), set.glyphs.size()), byInput), "array"};
}

}  // namespace tg::app
