// From a ParaView dataset to the mapper's input, and the sizing that every
// rank of a distributed run shares.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

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
inline constexpr const char* kIdArray = "tg_ids";          // the glyph's id: see Piece
inline constexpr const char* kSampleArray = "tg_scale_sample";  // sorted glyph magnitudes, all ranks
inline constexpr const char* kInfoArray = "tg_scale_info";      // see SizingInfo
inline constexpr const char* kBlockArray = "tg_blocks";  // composite input: (first id, flat index) per piece

// What the mapper needs of the whole dataset, over all ranks: the inputs of
// tensor::resolveScale, and the ranges the colour modes map.
struct SizingInfo {
  tensor::MagnitudeSample sample;
  double mdMin = 0, mdMax = 0, eigenMin = 0, eigenMax = 0;
};

// One dataset to glyph: a whole input (flatIndex 0), or one leaf block of a
// composite input with its flat index (ParaView's composite id).
struct Piece {
  vtkDataSet* data = nullptr;
  vtkDataArray* tensors = nullptr;  // null: the piece has none
  unsigned flatIndex = 0;
  vtkDataArray* mask = nullptr;     // a point array of one component, or none
};

// The CLI's selection of what is drawn, for a dataset in memory: --stride
// (io::Selector's rule: every N-th voxel along each axis of an image piece,
// by the indices of its extent, so that it does not depend on the ranks;
// every N-th point of other pieces, by glyph id) and --mask-min with the mask
// a point array of the piece (Piece::mask; kept where mask >= maskMin, the
// CLI's rule).
struct SelectionParams {
  long long stride = 1;
  double maskMin = 0.5;
};

// What a load left out or changed, over all ranks (sums and the maximum; a
// point that two ranks share counts on each): the CLI's load warnings
// (app::reportLoad), for the caller to report once.
struct LoadReport {
  std::size_t skippedNonFinite = 0;
  std::size_t skippedOverflow = 0;
  std::size_t kept = 0;        // tensors to draw
  std::size_t masked = 0;      // below SelectionParams::maskMin
  std::size_t unselected = 0;  // left out by the stride
  double maxAsymmetry = 0;          // io::asymmetry over the 9-component tensors
  std::size_t piecesWithTensors = 0;
  std::size_t piecesWithout = 0;    // pieces with points but no tensors (skipped)
};

// The points of the pieces whose tensor is finite (the CLI's rules:
// io::TensorField::addFull/addSym), as float positions, tensors in
// tensorglyph's order and ids; a piece's tensors hold 9 components (row-major
// 3x3, symmetrised), 6 in ParaView's order XX YY ZZ XY YZ XZ, or a 2-D
// tensor of 4 (XX YY ZZ XY) under OpenGeoSys's names sigma and epsilon, as the
// CLI reads them (io::tensorLikeArray, io::planarTensor). A glyph's id
// is its point id when `composite` is false (one piece); otherwise the pieces'
// points are numbered on in order and kBlockArray maps an id back to (flat
// index, point id); its pieces without tensors are skipped (counted in
// LoadReport::piecesWithout). The sizing sample and spacing are the whole
// dataset's, over the ranks of
// `controller` (a collective call; null: this process alone). Throws
// std::invalid_argument when a single piece has points but no tensors, or
// any piece's tensors have another component count or are not one tuple per
// point; after the collective calls, so that no rank is left waiting.
vtkSmartPointer<vtkPolyData> prepareGlyphInput(std::span<const Piece> pieces, bool composite,
                                               vtkMultiProcessController* controller,
                                               LoadReport* report = nullptr, const SelectionParams& select = {});

// The composite table of a prepared input: (first id, flat index) pairs in
// ascending id order; empty for a single dataset.
std::vector<std::uint32_t> blockTable(vtkPolyData* prepared);

// The glyphs of a prepared input (null or empty: none), and what
// prepareGlyphInput stored of the whole dataset.
tensor::GlyphSet buildGlyphSet(vtkPolyData* prepared);
SizingInfo sizingInfo(vtkPolyData* prepared);

// Each record's point of the prepared input (the point whose id it has):
// where a prepared point array's value for the record is.
std::vector<std::uint32_t> pointOfRecord(vtkPolyData* prepared, const tensor::GlyphSet& glyphs);

// The largest glyph id among the prepared points; -1 when none.
vtkIdType largestId(vtkPolyData* prepared);

// The points' bounds grown by the reach of the largest glyph of the whole
// dataset at `p` (no glyphs are built); false when there are no points.
bool glyphBounds(vtkPolyData* prepared, const tensor::ScaleParams& p, double out[6]);

}  // namespace tg::paraview
