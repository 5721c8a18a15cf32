#pragma once
// The scalars glyphs are coloured by, on the CPU: the twin of
// shaders/lib/color.glsl's colorScalar (the automatic windows, the legend
// and the tests read it), and which map and window a frame uses. GL-free.
#include <array>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "render/frame_params.h"
#include "tensor/glyph.h"

namespace tg::render {

// A mode that maps one scalar per glyph onto a colormap: all but DEC, DecFA and Sign.
bool colorIsScalar(ColorMode m);
// Signed quantities, drawn by default on the diverging map centred on zero:
// pressure, the principal values and the trace.
bool colorIsSigned(ColorMode m);
// Quantities in the tensor's own units (LegendParams::units): MD, the
// stress measures, the principal values, the trace and the sign colour's
// normal stress. FA, cl, cp and the directions have none; an array, its own.
bool colorHasTensorUnits(ColorMode m);
Colormap defaultColormap(ColorMode m);
// The legend's name of the quantity ("von Mises stress"); an array's is its name.
const char* colorQuantityName(ColorMode m);
const char* colormapName(Colormap m);

// shaders/lib/color.glsl's colorScalar in double, from descending
// eigenvalues `l` and FA; 0 for the modes that are no derived scalar.
// von Mises sqrt(((l1-l2)^2 + (l2-l3)^2 + (l3-l1)^2) / 2), Tresca l1 - l3,
// pressure -(l1+l2+l3)/3, trace l1+l2+l3, MD trace/3, s1..s3 l1..l3.
double colorScalar(ColorMode m, const double l[3], double fa);

// Each derived scalar's (min, max) over a set of glyphs, the zero tensors
// left out (a masked DTI background would pin every range at 0, as
// GlyphSet's MD range leaves them out); (+inf, -inf) where there is none.
struct ColorRanges {
  std::array<glm::dvec2, kColorModeCount> of;
  double maxAbsEigenvalue = 0;
  ColorRanges();
  void add(const ColorRanges& o);  // the union: of pieces, of ranks
};
ColorRanges colorRanges(std::span<const tensor::GlyphRecord> glyphs);
// The same over a set's records, with the set's MD range and largest
// |eigenvalue|: what an upload takes, and the whole field's ranges.
ColorRanges colorRanges(const tensor::GlyphSet& set);
// The finite values' (min, max); (+inf, -inf) for none.
glm::dvec2 finiteRange(std::span<const float> values);

// Values given one per input index (a file's point array, a NumPy array)
// in the records' order: record i takes byInput[glyphs[i].id], what
// GlyphRenderer::setColorScalars takes. Throws std::invalid_argument
// naming both counts when an id lies beyond byInput.
std::vector<float> scalarsByRecord(std::span<const tensor::GlyphRecord> glyphs, std::span<const float> byInput);

// The window frame `p` maps its scalar over: p.colorWindow where given, else
// `range` (the quantity's over the field), symmetric about zero on the
// diverging map; FA, cl and cp 0..1. Sign: (-M, M), M = max(|lo|, |hi|) of
// p.colorWindow, else `maxAbsEigenvalue`. No range: (0, 0), the map's middle.
glm::dvec2 resolveColorWindow(const FrameParams& p, glm::dvec2 range, double maxAbsEigenvalue);
inline Colormap resolveColormap(const FrameParams& p) { return p.colormap.value_or(defaultColormap(p.color)); }

}  // namespace tg::render
