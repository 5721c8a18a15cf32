#pragma once
// The one place where voxels of any volume format become world-space
// samples: index -> WC placement, the tensor frame (D_WC = T D Tᵀ), the
// confidence threshold and the selection. NRRD and NIfTI readers decode
// their data into it in file order (i fastest).
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "io/core/selection.h"
#include "io/field/tensor_field.h"
#include "util/huge_pages.h"

namespace tg::io {

struct VolumeGeometry {
  int dims[3] = {1, 1, 1};
  double originWC[3] = {0, 0, 0};
  double axesWC[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major; column k is one step along index k, in WC
  std::optional<std::array<double, 9>> tensorToWC;  // row-major T; none: the identity
};

void positionWC(const VolumeGeometry& g, const int ijk[3], double pWC[3]);
GridPlacement placementOf(const VolumeGeometry& g);

// Where the six unique components sit among a voxel's values.
struct ComponentLayout {
  int count = 6;            // values per voxel
  int confidence = -1;      // index of the confidence value, -1: none
  bool full = false;        // 9 values, row-major 3x3, symmetrised on load
  std::array<int, 6> sym{0, 1, 2, 3, 4, 5};  // value index of xx xy xz yy yz zz
};

class VolumeSink {
 public:
  VolumeSink(TensorField& f, const VolumeGeometry& g, const ComponentLayout& layout, const Selector& sel,
             double confidenceMin);
  // The next voxel's `layout.count` values, in file order.
  void push(const double* v);
  // The next `values / layout.count` voxels' values, in file order.
  void pushVoxels(const double* v, std::size_t values);
  // For readers that learn a voxel's values out of order (NIfTI stores one
  // volume per component): accept() decides, before any data, whether voxel
  // `index` is kept, counting it if not; pushAccepted() then delivers a kept
  // voxel's values.
  bool accept(std::uint64_t index);
  void pushAccepted(std::uint64_t index, const double* v);
  // Fills f.grid and f.sampleSpacing from the geometry.
  void finish();
  // Asymmetric 3D-matrix input: the largest |D - Dᵀ| / |D| seen.
  double maxAsymmetry() const { return maxAsym_; }
  // A warning in the field where that exceeds 1e-3: the tensors are drawn
  // symmetrised, which the user should know.
  void warnIfAsymmetric();

 private:
  void positionOf(std::uint64_t index, double pWC[3]) const;
  // The position of the voxel push() takes next, stepping to the one after.
  void nextPosition(double pWC[3]);
  void emit(std::uint64_t index, const double pWC[3], const double* v);
  TensorField& f_;
  VolumeGeometry g_;
  ComponentLayout layout_;
  const Selector& sel_;
  double confidenceMin_;
  std::uint64_t next_ = 0;
  int ijk_[3] = {0, 0, 0};
  double maxAsym_ = 0;
};

// Values gathered in single precision until their voxels are complete (the
// readers whose files hold one volume per component). A finite value beyond
// FLT_MAX becomes Inf in a float, and its tensor would be counted as the
// file's NaN/Inf rather than as overflow (an attacker run found MRtrix counts
// differing by layout); such values are marked and read back as a finite
// stand-in beyond FLT_MAX, which TensorField::addSym counts as overflow.
class FloatGather {
 public:
  void reserve(std::size_t n) { util::reserveHuge(values_, n); }
  void resize(std::size_t n) { values_.resize(n); }
  void set(std::size_t k, double v) {
    values_[k] = float(v);
    if (std::isinf(values_[k]) && std::isfinite(v)) [[unlikely]] mark(k);
  }
  void push_back(double v) {
    values_.push_back(float(v));
    if (std::isinf(values_.back()) && std::isfinite(v)) [[unlikely]] mark(values_.size() - 1);
  }
  double get(std::size_t k) const {
    return k < beyond_.size() && beyond_[k] ? std::copysign(1e300, double(values_[k])) : double(values_[k]);
  }
  const std::vector<float>& floats() const { return values_; }

 private:
  void mark(std::size_t k) {
    if (beyond_.size() <= k) beyond_.resize(std::max(values_.capacity(), k + 1));
    beyond_[k] = 1;
  }
  std::vector<float> values_;
  std::vector<char> beyond_;  // empty until a value is marked
};

double determinant3(const double m[9]);  // row-major

// Whether the steps of the axes holding more than one sample (`axes` row-major,
// column k one step along index k) fail to span as many dimensions as there
// are such axes: a zero, non-finite or parallel step, which would draw every
// sample along it on one point or plane. Relative to the steps' lengths, as
// MRtrix's transform check is.
bool gridIsSingular(const int dims[3], const double axes[9]);

// Polar decomposition's rotation (or rotation-reflection, if det < 0) of a
// row-major 3x3, which strips scaling and shear from an affine's linear part
// (Higham's iteration, "Computing the polar decomposition", 1986).
std::array<double, 9> orthogonalPart(const double m[9]);

}  // namespace tg::io
