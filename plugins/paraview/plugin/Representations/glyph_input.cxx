#include "glyph_input.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <vtkCommunicator.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMultiProcessController.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeUInt32Array.h>

#include "global_sample.h"
#include "io/core/selection.h"
#include "io/field/tensor_field.h"

namespace tg::paraview {
namespace {

// xx xy xz yy yz zz from ParaView's symmetric order XX YY ZZ XY YZ XZ.
void symFromParaView(const double* t, double s6[6]) {
  s6[0] = t[0];
  s6[1] = t[3];
  s6[2] = t[5];
  s6[3] = t[1];
  s6[4] = t[4];
  s6[5] = t[2];
}

double gridSpacing(vtkDataSet* input) {
  auto* image = vtkImageData::SafeDownCast(input);
  if (!image) return 0.0;
  int dims[3];
  double spacing[3];
  image->GetDimensions(dims);
  image->GetSpacing(spacing);
  double s = INFINITY;
  for (int k = 0; k < 3; ++k)
    if (dims[k] > 1) s = std::min(s, std::abs(spacing[k]));
  return std::isfinite(s) ? s : 0.0;
}

template <class T>
vtkSmartPointer<vtkDoubleArray> doubles(const char* name, const T& values) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfTuples(vtkIdType(values.size()));
  std::copy(values.begin(), values.end(), a->GetPointer(0));
  return a;
}

// Where io::Selector finds a piece's points: an image piece by the indices
// of its extent (the whole grid's, so that a stride does not depend on how
// the ranks split it), any other piece by glyph id as a point set.
struct PointIndex {
  bool grid = false;
  int dims[3] = {0, 0, 0};       // the grid the extent lies in
  int ext[6] = {0, 0, 0, 0, 0, 0};
  std::uint64_t of(vtkIdType i, std::uint64_t id) const {
    if (!grid) return id;
    const vtkIdType nx = ext[1] - ext[0] + 1, ny = ext[3] - ext[2] + 1;
    const auto gi = std::uint64_t(i % nx + ext[0]), gj = std::uint64_t(i / nx % ny + ext[2]),
               gk = std::uint64_t(i / (nx * ny) + ext[4]);
    return gi + std::uint64_t(dims[0]) * (gj + std::uint64_t(dims[1]) * gk);
  }
};

PointIndex pointIndex(vtkDataSet* input) {
  PointIndex ix;
  auto* image = vtkImageData::SafeDownCast(input);
  if (!image) return ix;
  image->GetExtent(ix.ext);
  // An extent below index 0 is numbered from its own corner.
  if (ix.ext[0] < 0 || ix.ext[2] < 0 || ix.ext[4] < 0)
    for (int k = 0; k < 3; ++k) {
      ix.ext[2 * k + 1] -= ix.ext[2 * k];
      ix.ext[2 * k] = 0;
    }
  for (int k = 0; k < 3; ++k) ix.dims[k] = ix.ext[2 * k + 1] + 1;
  ix.grid = true;
  return ix;
}

// Reads one piece into `f`, its points numbered from `firstId`; the problem,
// or "" when it is fine. A problem is reported after the collective calls, so
// that the other ranks are not left waiting in them.
std::string readPiece(const Piece& piece, std::uint64_t firstId, const SelectionParams& select, io::TensorField& f,
                      LoadReport& report) {
  vtkDataSet* input = piece.data;
  vtkDataArray* tensors = piece.tensors;
  const vtkIdType n = input ? input->GetNumberOfPoints() : 0;
  if (n == 0) return "";
  const std::string where = piece.flatIndex ? "block " + std::to_string(piece.flatIndex) + ": " : "";
  if (!tensors)
    return "prepareGlyphInput: " + where + std::to_string(n) + " points but no point array of tensors (9 or 6 components)";
  const std::string name = tensors->GetName() ? tensors->GetName() : "";
  const int nc = tensors->GetNumberOfComponents();
  if (!io::tensorLikeArray(nc, name))
    return "prepareGlyphInput: " + where + "array '" + name + "' has " + std::to_string(nc) +
           " components; tensors need 9 (3x3), 6 (XX YY ZZ XY YZ XZ) or 4 (2-D XX YY ZZ XY, named sigma or epsilon "
           "as OpenGeoSys writes them)";
  // A cell array (chosen from Python: the property's list offers point
  // arrays only) has one tuple per cell: read per point, it is out of bounds
  // or another cell's tensor.
  if (tensors->GetNumberOfTuples() != n)
    return "prepareGlyphInput: " + where + "array '" + name + "' has " + std::to_string(tensors->GetNumberOfTuples()) +
           " tuples for " + std::to_string(n) + " points; the tensors must be point data";
  vtkDataArray* mask = piece.mask;
  if (mask && (mask->GetNumberOfComponents() != 1 || mask->GetNumberOfTuples() != n))
    return "prepareGlyphInput: " + where + "mask array '" + (mask->GetName() ? mask->GetName() : "") + "' has " +
           std::to_string(mask->GetNumberOfComponents()) + " components and " +
           std::to_string(mask->GetNumberOfTuples()) + " tuples; a mask is one value per point";
  if (firstId + std::uint64_t(n) > io::kMaxInputs)
    return "prepareGlyphInput: " + std::to_string(firstId + std::uint64_t(n)) + " points; at most " +
           std::to_string(io::kMaxInputs) + " fit the id channel";
  const PointIndex index = pointIndex(input);
  io::Selection sel;
  sel.stride = select.stride;
  const io::Selector selector(sel, "prepareGlyphInput", index.grid ? index.dims : nullptr);
  double p[3], t[9], s6[6], full[9];
  for (vtkIdType i = 0; i < n; ++i) {
    input->GetPoint(i, p);
    const auto id = std::uint32_t(firstId + std::uint64_t(i));
    if (!selector.admit(index.of(i, id), p, f)) continue;
    if (mask && !(mask->GetComponent(i, 0) >= select.maskMin)) {
      ++f.totalPoints;
      ++f.masked;
      continue;
    }
    tensors->GetTuple(i, t);
    if (nc == 9) {
      // As io/modules/vtk/vtk_reader.cpp measures it, for the same warning.
      report.maxAsymmetry = std::max(report.maxAsymmetry, io::asymmetry(t));
      f.addFull(id, p, t);
    } else if (nc == 6) {
      symFromParaView(t, s6);
      f.addSym(id, p, s6);
    } else {
      io::planarTensor(nc, t, full);
      f.addFull(id, p, full);
    }
  }
  return "";
}

// The grid spacing when every piece with points is an image (the smallest),
// else 0: the caller estimates it from the points.
double piecesGridSpacing(std::span<const Piece> pieces) {
  double s = INFINITY;
  for (const Piece& piece : pieces) {
    if (!piece.data || !piece.tensors || piece.data->GetNumberOfPoints() == 0) continue;
    const double g = gridSpacing(piece.data);
    if (!(g > 0.0)) return 0.0;
    s = std::min(s, g);
  }
  return std::isfinite(s) ? s : 0.0;
}

// Where a piece's points are numbered from (its first glyph id).
struct PieceStart {
  std::uint64_t firstId;
  const Piece* piece;
};

// Every numeric point array of the pieces, one tuple per kept glyph in the
// prepared order (`keptIds`), under its own name: what ParaView's ColorBy
// may pick, in the data delivered to whichever process renders, so that a
// new pick takes no new RequestData and no new glyphs. A piece without the
// array (or with another component count) gives NaN.
void addPointArrays(std::span<const PieceStart> starts, std::span<const std::uint32_t> keptIds, vtkPolyData* out) {
  std::vector<vtkDataArray*> first;  // the first piece's array of each name
  for (const PieceStart& s : starts) {
    vtkPointData* pd = s.piece->data->GetPointData();
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a) {
      vtkDataArray* array = pd->GetArray(a);
      const char* name = array ? array->GetName() : nullptr;
      if (!name || out->GetPointData()->HasArray(name) ||
          std::any_of(first.begin(), first.end(), [&](vtkDataArray* f) { return std::string(f->GetName()) == name; }))
        continue;
      first.push_back(array);
    }
  }
  for (vtkDataArray* like : first) {
    vtkSmartPointer<vtkDataArray> copy;
    copy.TakeReference(like->NewInstance());
    copy->SetName(like->GetName());
    const int nc = like->GetNumberOfComponents();
    copy->SetNumberOfComponents(nc);
    copy->SetNumberOfTuples(vtkIdType(keptIds.size()));
    for (std::size_t k = 0; k < keptIds.size(); ++k) {
      const auto at = std::upper_bound(starts.begin(), starts.end(), std::uint64_t(keptIds[k]),
                                       [](std::uint64_t id, const PieceStart& s) { return id < s.firstId; });
      const PieceStart& s = *(at - 1);
      vtkDataArray* src = s.piece->data->GetPointData()->GetArray(like->GetName());
      const auto local = vtkIdType(std::uint64_t(keptIds[k]) - s.firstId);
      if (src && src->GetNumberOfComponents() == nc && local < src->GetNumberOfTuples())
        copy->SetTuple(vtkIdType(k), local, src);
      else
        for (int c = 0; c < nc; ++c) copy->SetComponent(vtkIdType(k), c, NAN);
    }
    out->GetPointData()->AddArray(copy);
  }
}

}  // namespace

vtkSmartPointer<vtkPolyData> prepareGlyphInput(std::span<const Piece> pieces, bool composite,
                                               vtkMultiProcessController* controller, LoadReport* reportOut,
                                               const SelectionParams& select) {
  io::TensorField f;
  LoadReport report;
  std::string problem;
  std::vector<std::uint32_t> blocks;  // (first id, flat index)
  std::uint64_t nextId = 0;
  std::vector<PieceStart> starts;
  for (const Piece& piece : pieces) {
    const vtkIdType n = piece.data ? piece.data->GetNumberOfPoints() : 0;
    if (composite && n > 0 && !piece.tensors) {
      ++report.piecesWithout;  // blocks without the array are not drawn, as ParaView's Tensor Glyph skips them
      continue;
    }
    if (n > 0) ++report.piecesWithTensors;
    std::string p = readPiece(piece, nextId, select, f, report);
    if (!p.empty()) {
      if (problem.empty()) problem = std::move(p);
      continue;
    }
    if (n > 0) starts.push_back({nextId, &piece});
    if (composite && n > 0) {
      blocks.push_back(std::uint32_t(nextId));
      blocks.push_back(piece.flatIndex);
    }
    nextId += std::uint64_t(n);
  }
  report.skippedNonFinite = f.skippedNonFinite;
  report.skippedOverflow = f.skippedOverflow;
  report.kept = f.size();
  report.masked = f.masked;
  report.unselected = f.unselected;
  const std::size_t kept = f.size();
  const tensor::GlyphSet glyphs = tensor::buildGlyphs(f.positions, f.tensors, f.ids);
  const bool any = kept > 0;
  SizingInfo info;
  // Collective: the sample and spacing of the whole dataset, whatever the ranks.
  info.sample = globalMagnitudeSample(glyphs, any ? piecesGridSpacing(pieces) : INFINITY, controller);
  info.mdMin = any ? glyphs.mdMin : INFINITY;
  info.mdMax = any ? glyphs.mdMax : -INFINITY;
  info.eigenMin = any ? glyphs.eigenvalueMin : INFINITY;
  info.eigenMax = any ? glyphs.eigenvalueMax : -INFINITY;

  if (controller && controller->GetNumberOfProcesses() > 1) {
    // Every rank colours by the whole dataset's ranges, as it sizes by its
    // sample (globalMagnitudeSample), so that a distributed picture equals
    // the serial one.
    const double lows[2] = {info.mdMin, info.eigenMin};
    const double highs[2] = {info.mdMax, info.eigenMax};
    double lowOut[2], highOut[2];
    controller->AllReduce(lows, lowOut, 2, vtkCommunicator::MIN_OP);
    controller->AllReduce(highs, highOut, 2, vtkCommunicator::MAX_OP);
    info.mdMin = lowOut[0];
    info.eigenMin = lowOut[1];
    info.mdMax = highOut[0];
    info.eigenMax = highOut[1];
    // The load's warnings, said once for the whole dataset.
    const double loadCounts[7] = {double(report.skippedNonFinite), double(report.skippedOverflow),
                                  double(report.piecesWithTensors), double(report.piecesWithout),
                                  double(report.masked), double(report.unselected), double(report.kept)};
    double countsOut[7];
    controller->AllReduce(loadCounts, countsOut, 7, vtkCommunicator::SUM_OP);
    report.skippedNonFinite = std::size_t(countsOut[0]);
    report.skippedOverflow = std::size_t(countsOut[1]);
    report.piecesWithTensors = std::size_t(countsOut[2]);
    report.piecesWithout = std::size_t(countsOut[3]);
    report.masked = std::size_t(countsOut[4]);
    report.unselected = std::size_t(countsOut[5]);
    report.kept = std::size_t(countsOut[6]);
    double asym = report.maxAsymmetry;
    controller->AllReduce(&asym, &report.maxAsymmetry, 1, vtkCommunicator::MAX_OP);
  }
  if (reportOut) *reportOut = report;

  auto out = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(vtkIdType(kept));
  auto tensorOut = vtkSmartPointer<vtkFloatArray>::New();
  tensorOut->SetName(kTensorArray);
  tensorOut->SetNumberOfComponents(6);
  tensorOut->SetNumberOfTuples(vtkIdType(kept));
  auto ids = vtkSmartPointer<vtkTypeUInt32Array>::New();
  ids->SetName(kIdArray);
  ids->SetNumberOfTuples(vtkIdType(kept));
  if (kept > 0) {
    std::copy(f.positions.begin(), f.positions.end(), static_cast<float*>(points->GetVoidPointer(0)));
    std::copy(f.tensors.begin(), f.tensors.end(), tensorOut->GetPointer(0));
    std::copy(f.ids.begin(), f.ids.end(), ids->GetPointer(0));
  }
  out->SetPoints(points);
  out->GetPointData()->AddArray(tensorOut);
  out->GetPointData()->AddArray(ids);
  if (kept > 0) addPointArrays(starts, std::span(f.ids.data(), f.ids.size()), out);
  out->GetFieldData()->AddArray(doubles(kSampleArray, info.sample.sorted));
  const double scalars[6] = {info.sample.maxAbs, info.sample.spacing, info.mdMin, info.mdMax, info.eigenMin,
                             info.eigenMax};
  out->GetFieldData()->AddArray(doubles(kInfoArray, std::span<const double>(scalars)));
  if (composite) {
    auto table = vtkSmartPointer<vtkTypeUInt32Array>::New();
    table->SetName(kBlockArray);
    table->SetNumberOfTuples(vtkIdType(blocks.size()));
    std::copy(blocks.begin(), blocks.end(), table->GetPointer(0));
    out->GetFieldData()->AddArray(table);
  }
  if (!problem.empty()) throw std::invalid_argument(problem);
  return out;
}

tensor::GlyphSet buildGlyphSet(vtkPolyData* prepared) {
  const vtkIdType n = prepared ? prepared->GetNumberOfPoints() : 0;
  auto* t = n ? vtkFloatArray::SafeDownCast(prepared->GetPointData()->GetArray(kTensorArray)) : nullptr;
  auto* ids = n ? vtkTypeUInt32Array::SafeDownCast(prepared->GetPointData()->GetArray(kIdArray)) : nullptr;
  auto* pts = n ? vtkFloatArray::SafeDownCast(prepared->GetPoints()->GetData()) : nullptr;
  if (!t || !ids || !pts) return tensor::buildGlyphs({}, {}, {});
  const std::size_t count = std::size_t(n);
  return tensor::buildGlyphs({pts->GetPointer(0), 3 * count}, {t->GetPointer(0), 6 * count},
                             {ids->GetPointer(0), count});
}

SizingInfo sizingInfo(vtkPolyData* prepared) {
  SizingInfo info;
  if (!prepared) return info;
  auto* sample = vtkDoubleArray::SafeDownCast(prepared->GetFieldData()->GetArray(kSampleArray));
  auto* scalars = vtkDoubleArray::SafeDownCast(prepared->GetFieldData()->GetArray(kInfoArray));
  if (!sample || !scalars || scalars->GetNumberOfTuples() != 6) return info;
  info.sample.sorted.assign(sample->GetPointer(0), sample->GetPointer(0) + sample->GetNumberOfTuples());
  const double* s = scalars->GetPointer(0);
  info.sample.maxAbs = s[0];
  info.sample.spacing = s[1];
  info.mdMin = s[2];
  info.mdMax = s[3];
  info.eigenMin = s[4];
  info.eigenMax = s[5];
  return info;
}

std::vector<std::uint32_t> blockTable(vtkPolyData* prepared) {
  auto* table = prepared ? vtkTypeUInt32Array::SafeDownCast(prepared->GetFieldData()->GetArray(kBlockArray)) : nullptr;
  if (!table) return {};
  return {table->GetPointer(0), table->GetPointer(0) + table->GetNumberOfTuples()};
}

std::vector<std::uint32_t> pointOfRecord(vtkPolyData* prepared, const tensor::GlyphSet& glyphs) {
  const vtkIdType n = prepared ? prepared->GetNumberOfPoints() : 0;
  auto* ids = n ? vtkTypeUInt32Array::SafeDownCast(prepared->GetPointData()->GetArray(kIdArray)) : nullptr;
  if (!ids) return {};
  std::vector<std::uint32_t> pointOfId(std::size_t(largestId(prepared)) + 1, 0);
  for (vtkIdType j = 0; j < n; ++j) pointOfId[ids->GetValue(j)] = std::uint32_t(j);
  std::vector<std::uint32_t> out(glyphs.glyphs.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = pointOfId[glyphs.glyphs[i].id];
  return out;
}

vtkIdType largestId(vtkPolyData* prepared) {
  const vtkIdType n = prepared ? prepared->GetNumberOfPoints() : 0;
  auto* ids = n ? vtkTypeUInt32Array::SafeDownCast(prepared->GetPointData()->GetArray(kIdArray)) : nullptr;
  if (!ids) return -1;
  return vtkIdType(*std::max_element(ids->GetPointer(0), ids->GetPointer(0) + n));
}

bool glyphBounds(vtkPolyData* prepared, const tensor::ScaleParams& p, double out[6]) {
  if (!prepared || prepared->GetNumberOfPoints() == 0) return false;
  const SizingInfo info = sizingInfo(prepared);
  const tensor::ResolvedScale sized = tensor::resolveScale(p, info.sample);
  const double reach = tensor::kGlyphReach * tensor::glyphRadiusWC(sized.scale, sized.mapping, info.sample.maxAbs);
  prepared->GetPoints()->GetBounds(out);
  for (int k = 0; k < 3; ++k) {
    out[2 * k] -= reach;
    out[2 * k + 1] += reach;
  }
  return true;
}

}  // namespace tg::paraview
