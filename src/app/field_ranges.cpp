#include "app/field_ranges.h"

#include <span>

#include "tensor/glyph.h"

namespace tg::app {

bool selectsPart(const io::ReadOptions& read) {
  const io::Selection& s = read.selection;
  return s.slice || s.stride > 1 || s.roiWC || !s.maskPath.empty();
}

std::optional<render::ColorRanges> wholeFieldColorRanges(
    const RenderOptions& o, const std::function<io::TensorField(const io::ReadOptions&)>& load) {
  if (!load || !selectsPart(o.field.read)) return std::nullopt;
  io::ReadOptions all = o.field.read;
  const double confidenceMin = all.selection.confidenceMin;  // which tensors a file holds, not a selection
  all.selection = {};
  all.selection.confidenceMin = confidenceMin;
  all.progress = {};
  const io::TensorField f = load(all);
  const tensor::GlyphSet set = tensor::buildGlyphs(f.positions, f.tensors, f.ids, 0, o.field.glyph);
  render::ColorRanges r = render::colorRanges(std::span(set.glyphs.data(), set.glyphs.size()));
  r.of[std::size_t(render::ColorMode::MD)] = glm::dvec2(set.mdMin, set.mdMax);
  r.maxAbsEigenvalue = set.maxAbsEigenvalue;
  if (!f.colorValues.empty())
    r.of[std::size_t(render::ColorMode::Array)] = render::finiteRange(std::span(f.colorValues.data(), f.colorValues.size()));
  return r;
}

}  // namespace tg::app
