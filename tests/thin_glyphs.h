#pragma once
// A field without its glyphs of a zero (or nearly zero) eigenvalue: those
// are kMinAxisRatio (1e-7) of their size thick, and a float march through
// them runs at GC coordinates near 1e6 (lib/superquadric_march.glsl), where
// two float implementations of the same source may each cover a few pixels
// the other does not. The CPU path's exactness tests compare the rest
// strictly and those separately.
#include <algorithm>
#include <cmath>

#include "io/field/tensor_field.h"
#include "tensor/glyph.h"

namespace tg::test {

inline tensor::GlyphSet withoutFlatGlyphs(const io::TensorField& f, double ratio = 1e-5) {
  const tensor::GlyphSet all = tensor::buildGlyphs(f.positions, f.tensors, f.ids);
  std::vector<float> pos, ten;
  std::vector<std::uint32_t> ids;
  for (const tensor::GlyphRecord& g : all.glyphs) {
    double lo = INFINITY, hi = 0;
    for (const float l : g.eigenvalues) {
      lo = std::min(lo, double(std::abs(l)));
      hi = std::max(hi, double(std::abs(l)));
    }
    if (!(lo >= ratio * hi) || hi == 0) continue;
    const std::size_t i = std::size_t(std::find(f.ids.begin(), f.ids.end(), g.id) - f.ids.begin());
    pos.insert(pos.end(), f.positions.begin() + std::ptrdiff_t(3 * i), f.positions.begin() + std::ptrdiff_t(3 * i + 3));
    ten.insert(ten.end(), f.tensors.begin() + std::ptrdiff_t(6 * i), f.tensors.begin() + std::ptrdiff_t(6 * i + 6));
    ids.push_back(g.id);
  }
  return tensor::buildGlyphs(pos, ten, ids);
}

}  // namespace tg::test
