// From a ParaView dataset to the mapper's input, and the sizing that every
// rank of a distributed run shares.
#pragma once
#include <cstddef>
#include <span>

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include "tensor/glyph.h"
#include "tensor/glyph_scale.h"

class vtkDataArray;
class vtkDataSet;
class vtkMultiProcessController;
class vtkPolyData;

namespace tg::paraview {

// Names of what prepareGlyphInput writes.
inline constexpr const char* kTensorArray = "tg_tensor6";  // xx xy xz yy yz zz, float
inline constexpr const char* kIdArray = "tg_ids";          // the point's index in its input
inline constexpr const char* kSampleArray = "tg_scale_sample";  // sorted glyph magnitudes, all ranks
inline constexpr const char* kInfoArray = "tg_scale_info";      // see SizingInfo

// What the mapper needs of the whole dataset, over all ranks: the inputs of
// tensor::resolveScale, and the ranges the colour modes map.
struct SizingInfo {
  tensor::MagnitudeSample sample;
  double mdMin = 0, mdMax = 0, eigenMin = 0, eigenMax = 0;
};

// The points of `input` whose tensor in `tensors` is finite (the CLI's
// rules: io::TensorField::addFull/addSym), as float positions, tensors in
// tensorglyph's order and ids; `tensors` holds 9 components (row-major 3x3,
// symmetrised) or 6 in ParaView's order XX YY ZZ XY YZ XZ. The sizing sample
// is merged over the ranks of `controller` (a collective call; null: this
// process alone). Throws std::invalid_argument when `input` has points but
// `tensors` is null, has another component count, or is not one tuple per
// point; after the collective calls, so that no rank is left waiting.
// `skipped` (when given) receives how many of this rank's points were left
// out for NaN/Inf or values beyond single precision, for the caller to report.
vtkSmartPointer<vtkPolyData> prepareGlyphInput(vtkDataSet* input, vtkDataArray* tensors,
                                               vtkMultiProcessController* controller,
                                               std::size_t* skipped = nullptr);

// The glyphs of a prepared input (null or empty: none), and what
// prepareGlyphInput stored of the whole dataset.
tensor::GlyphSet buildGlyphSet(vtkPolyData* prepared);
SizingInfo sizingInfo(vtkPolyData* prepared);

// The largest input point id among the prepared points; -1 when none.
vtkIdType largestId(vtkPolyData* prepared);

// The points' bounds grown by the reach of the largest glyph of the whole
// dataset at `p` (no glyphs are built); false when there are no points.
bool glyphBounds(vtkPolyData* prepared, const tensor::ScaleParams& p, double out[6]);

}  // namespace tg::paraview
