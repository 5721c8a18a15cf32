// ParaView's colouring of a display (ColorBy: a point array through the
// display's lookup table) as the renderer's ColorMode::Array takes it: one
// scalar per glyph record and the table's own colours
// (GlyphRenderer::setColorTable), so that the glyphs' colours are the scalar
// bar's. A new range or preset resamples the table and moves the window;
// the records and scalars stay uploaded.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

class vtkDataArray;
class vtkScalarsToColors;

namespace tg::paraview {

// How the table reads an array: the lookup table's VectorMode (magnitude
// or one component of a multi-component array) and its log scale.
struct LookupReading {
  bool magnitude = true;
  int component = 0;
  bool log = false;
  bool operator==(const LookupReading&) const = default;
};
LookupReading lookupReading(vtkScalarsToColors* lut);

// The values the window maps, one per record: the array's tuple at each
// record's prepared point (`pointOfRecord`), read as `r` says (log10 with a
// log scale; NaN where the value has none).
std::vector<float> lookupScalars(vtkDataArray* array, std::span<const std::uint32_t> pointOfRecord,
                                 const LookupReading& r);

// The table's colours and window in the space the scalars are in: its
// colours for as many equal parts of its range as it has (a discretised
// table's own count; 1024 samples of a continuous one), then its NaN,
// below-range and above-range colours, each what lut->MapValue gives.
struct LookupTable {
  std::vector<glm::vec4> colors;
  glm::dvec2 window{0.0, 1.0};
};
LookupTable sampleLookupTable(vtkScalarsToColors* lut, const LookupReading& r);

}  // namespace tg::paraview
