#pragma once
// Which samples of a field are loaded: slices and slabs, stride, a region of
// interest and a scalar mask. Applied while reading, so that unselected
// samples never take memory.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/field/tensor_field.h"

namespace tg::io {

// --slice axis:index[:thickness]: the voxels whose index along `axis` (0, 1, 2
// for i, j, k) lies in [index - (thickness-1)/2, index + thickness/2], a slab
// centred on `index`. An anatomical slice (axial:40) or a world position
// (z=12.5mm) names a world axis instead; resolveSlice() turns it into the
// voxel axis nearest that world axis and, for a position, the nearest index.
struct SliceSpec {
  // A voxel-axis slice; SliceSpec{2, 40, 5} reads as before the world forms.
  SliceSpec(int voxelAxis = 2, long long at = 0, long long slab = 1) : axis(voxelAxis), index(at), thickness(slab) {}
  int axis = 2;
  long long index = 0;
  long long thickness = 1;
  int worldAxis = -1;  // 0, 1, 2: x (R), y (A), z (S); -1: `axis` is the voxel axis given
  std::optional<double> positionWC;  // along worldAxis, in world units
  // As the user wrote it, in the canonical form: "z:40", "axial:40:3", "z=12.5mm".
  std::string text() const;
  bool operator==(const SliceSpec&) const = default;
};

// A --slice index beyond the grid: found only once the header is read, yet a
// command-line mistake, which the CLI reports as one (exit 2).
class SliceOutOfRange : public InputError {
 public:
  SliceOutOfRange(const std::string& what, const SliceSpec& s, int axisSize)
      : InputError(what), spec(s), size(axisSize) {}
  SliceSpec spec;
  int size;
};

struct ScalarVolume;

struct Selection {
  std::optional<SliceSpec> slice;  // grids only
  // Grids: every stride-th voxel along each axis, but a slice's own (its
  // slab is kept whole); point sets: every stride-th point.
  long long stride = 1;
  std::optional<std::array<double, 6>> roiWC;  // x0 y0 z0 x1 y1 z1, inclusive
  std::string maskPath;            // scalar volume on the same grid
  // The mask itself when it was given in memory (Python's arrays): read
  // instead of maskPath, which then only names it in messages.
  std::shared_ptr<const ScalarVolume> maskVolume;
  double maskMin = 0.5;            // keep where mask >= maskMin
  double confidenceMin = 0.5;      // 3D-masked-symmetric-matrix NRRD: keep where confidence >= this

  bool needsGrid() const { return slice.has_value() || !maskPath.empty(); }
};

// "z:10", "2:10:3", "x:0" (voxel axes: x, y, z are i, j, k, as ever);
// "axial:10", "coronal:10:3", "sagittal:0" (the voxel axis nearest S, A or
// R); "z=12.5mm", "axial=12.5", "x=-3:2" (the slice nearest that world
// position, "mm" optional). Throws std::invalid_argument with a one-line reason.
SliceSpec parseSlice(const std::string& text);

// Where a grid's voxels lie: voxel (i, j, k) at originWC + axesWC (i j k)ᵀ.
struct GridPlacement;
// `s` with its voxel axis and index found on this grid: for a world axis,
// the voxel axis whose direction lies nearest it (on an oblique grid, the
// one most nearly along it) and, for a position, the index of the slice
// through it at the grid's centre (rounded; it may lie outside the grid).
// A voxel-axis slice comes back as given.
SliceSpec resolveSlice(const SliceSpec& s, const GridPlacement& placement, const int dims[3]);

struct GridPlacement {
  double originWC[3] = {0, 0, 0};
  double axesWC[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major; column k is one step along index k
};

// A scalar volume, as a mask is given: NRRD, NIfTI, MRtrix or .vti, one value per voxel.
struct ScalarVolume {
  int dims[3] = {0, 0, 0};
  std::vector<float> values;  // i fastest
  // Where the file says its voxels lie (an sform or qform, a transform, space
  // directions, a .vti's origin and spacing); none when it does not say.
  std::optional<GridPlacement> placement;
};
// A regular file only (a FIFO would block), on the grid `dims`: a mask of
// another grid is refused before any of its data is decoded. dims null: any
// grid that fits in memory (an underlay).
ScalarVolume readScalarVolume(const std::string& path, const int* dims);
// "AxBxC", for messages.
std::string gridText(const int dims[3]);
// "" when a mask's grid `got` is the tensors' `want`; else the message that
// every mask reader gives before decoding anything. want null (an underlay):
// "" when its values fit in the memory a load may use.
std::string maskGridMismatch(const int got[3], const int* want);

// The per-sample decision, built once per read after the header is known.
class Selector {
 public:
  enum class Verdict { Keep, Unselected, Masked };
  // dims: the grid's, or null for a point set. Throws InputError naming
  // `path` when the selection does not fit the data (a slice beyond the grid,
  // a mask of another size or placed elsewhere, a slice of a point set).
  // `placement`: the tensor grid's, compared with the mask's own.
  Selector(const Selection& sel, const std::string& path, const int* dims, const GridPlacement* placement = nullptr);
  Verdict judge(std::uint64_t index, const double pWC[3]) const;
  // judge() for a reader: true to keep the sample; otherwise counts it in
  // f (total and masked or unselected) and returns false.
  // Inline for the per-voxel common case, selecting everything.
  bool admit(std::uint64_t index, const double pWC[3], TensorField& f) const {
    return all_ || admitJudged(index, pWC, f);
  }
  bool selectsAll() const { return all_; }
  // At most how many of `n` samples the slice and stride can keep: what a
  // reader promises before decoding (ROI and mask only keep fewer).
  std::uint64_t keptBound(std::uint64_t n) const;
  // The kept samples' spacing on a grid of these axis `spacing`s: each axis
  // that keeps more than one sample, thinned by the stride (which spares a
  // slice's own axis); INFINITY when none does.
  double keptSpacing(const double spacing[3]) const;
  // The slice as applied, in voxel terms (resolveSlice); none without one.
  const std::optional<SliceSpec>& slice() const { return sel_.slice; }

 private:
  bool admitJudged(std::uint64_t index, const double pWC[3], TensorField& f) const;
  Selection sel_;
  int dims_[3] = {0, 0, 0};
  bool grid_ = false, all_ = true;
  long long slabLo_ = 0, slabHi_ = -1;
  ScalarVolume mask_;
};

// The selection applied after the fact, to a field already in memory (the
// built-in scene). ids must be the samples' input indices.
void applySelection(TensorField& f, const Selection& sel);

}  // namespace tg::io
