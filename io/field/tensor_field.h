#pragma once
// A tensor field as loaded from any format: points in WC and tensors already
// in the world frame.
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "util/mapped_array.h"

namespace tg::io {

// Input indices run below this: the id channel's values from here up name
// context items and "nothing drawn" (render/context_item.h).
inline constexpr std::uint64_t kMaxInputs = 0xFFFFFF00u;

// Bad input. what() is one line: "function: file: problem".
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct GridInfo {
  int dims[3] = {0, 0, 0};
  double spacing[3] = {0, 0, 0};
  double origin[3] = {0, 0, 0};
  double directions[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major: column k is axis k in WC
};

// A frame --frame could name for a volume, and the map it would apply (none:
// the identity), for the frame check (app/frame_check.h).
struct FrameChoice {
  std::string name;
  std::optional<std::array<double, 9>> tensorToWC;
};

struct TensorField {
  std::string path;
  std::string description;  // dataset type and size, for `info`
  std::string arrayName;
  std::string space;        // world space of the positions, e.g. "RAS"; "" when the format has none
  std::string lengthUnits;  // of the positions, as the header names them ("mm"); "" when it does not
  std::string layout;       // component order read from the file, for `info`
  std::optional<std::array<double, 9>> measurementFrame;  // row-major, as applied (D_WC = M D Mᵀ)
  // The tensor frame as read, for `info`: its name and why ("fsl: FSL's voxel
  // axes, i reversed as the affine's det > 0"), and the whole map applied,
  // D_WC = T D Tᵀ (none: the identity; tensors were stored in WC).
  std::string frame;
  std::optional<std::array<double, 9>> tensorToWC;  // row-major T
  // Volumes whose frame --frame chooses (NIfTI, arrays): the other frames
  // whose T differs from this one's.
  std::vector<FrameChoice> otherFrames;
  bool hasConfidence = false;  // the format gives each tensor a confidence (masked NRRD)
  std::vector<std::string> warnings;  // one line each, without the file name
  // Huge-page storage that grows without copies (util::MappedArray).
  util::MappedArray<float> positions;    // 3 per kept tensor, WC
  util::MappedArray<float> tensors;      // 6 per kept tensor: xx xy xz yy yz zz, WC
  util::MappedArray<std::uint32_t> ids;  // input index of each kept tensor
  // ReadOptions::colorArray's values, one per kept tensor (beside ids), as
  // named in the file; when the file has no point array of that name, none,
  // and `pointArrays` lists those it has ("name (N components), ...").
  util::MappedArray<float> colorValues;
  std::string colorArrayName, pointArrays;
  std::size_t totalPoints = 0;
  std::size_t skippedNonFinite = 0;
  std::size_t skippedOverflow = 0;  // |D| beyond single precision: its eigenvalues would be infinite
  std::size_t masked = 0;      // below the confidence or mask threshold
  std::size_t unselected = 0;  // outside the slice, stride or region of interest
  std::optional<GridInfo> grid;
  double sampleSpacing = 0;  // grid spacing, or the median nearest-neighbour distance

  std::size_t size() const { return ids.size(); }
  // Appends one tensor unless a component is NaN/Inf, or its Frobenius norm
  // (which bounds every |eigenvalue|) exceeds FLT_MAX; counts it skipped then.
  // t9 is a full row-major 3x3; it is symmetrised.
  void addFull(std::uint32_t id, const double p[3], const double t9[9]);
  // The same for a symmetric tensor given as xx xy xz yy yz zz. Inline: the
  // volume readers call it once a voxel.
  void addSym(std::uint32_t id, const double p[3], const double s6[6]) {
    ++totalPoints;
    if (!admits(p, s6)) return;
    storeSample(p, s6, positions.extend(3), tensors.extend(6));
    ids.push_back(id);
  }
  // addSym's test without the append: true, or false with the sample counted
  // skipped. A Frobenius norm within FLT_MAX bounds every component, so it
  // and the position's magnitudes say whether every float is finite (a
  // finite double beyond FLT_MAX would be stored as Inf); NaN fails each
  // comparison. Only a failure asks whether the file held a NaN/Inf or the
  // value overflowed.
  bool admits(const double p[3], const double s6[6]) {
    constexpr double kMax = FLT_MAX;
    const double norm2 = s6[0] * s6[0] + s6[3] * s6[3] + s6[5] * s6[5] + 2 * (s6[1] * s6[1] + s6[2] * s6[2] + s6[4] * s6[4]);
    const bool fits = norm2 <= kMax * kMax && std::abs(p[0]) <= kMax && std::abs(p[1]) <= kMax && std::abs(p[2]) <= kMax;
    if (!fits) [[unlikely]] {
      bool finite = true;
      for (int k = 0; k < 3; ++k) finite &= std::isfinite(p[k]);
      for (int k = 0; k < 6; ++k) finite &= std::isfinite(s6[k]);
      ++(finite ? skippedOverflow : skippedNonFinite);
      return false;
    }
    return true;
  }
  // An admitted sample as floats, straight into its slots: through a stack
  // copy, the stores and the wider reloads of it stalled on store
  // forwarding (half of a raw load's decode time).
  static void storeSample(const double p[3], const double s6[6], float* posWC, float* tensor) {
    for (int k = 0; k < 3; ++k) posWC[k] = float(p[k]);
    for (int k = 0; k < 6; ++k) tensor[k] = float(s6[k]);
  }
  void reserve(std::size_t n) {
    positions.reserve(3 * n);
    tensors.reserve(6 * n);
    ids.reserve(n);
  }
  // Frees positions, tensors and ids once glyphs have been built from them;
  // the counts and grid stay.
  void releaseSamples() {
    positions = {};
    tensors = {};
    ids = {};
    colorValues = {};
  }
};

// (D + Dᵀ)/2 of a row-major 3x3 as xx xy xz yy yz zz.
void symmetricPart(const double t9[9], double s6[6]);
// max |D - Dᵀ| / max |(D + Dᵀ)/2| of a row-major 3x3; 0 for a zero one.
double asymmetry(const double t9[9]);
// The warning a reader adds when the largest asymmetry of its 9-component
// tensors (`what`) exceeds 1e-3, since they are drawn symmetrised; empty below.
std::string asymmetryWarning(const std::string& what, double maxAsymmetry);
// T S Tᵀ for a symmetric S (xx xy xz yy yz zz) and a row-major 3x3 T: a
// tensor carried from one frame into another.
void congruence(const double t[9], const double s6[6], double out6[6]);

// Whether a point array of `components` named `name` is read as tensors
// without being named (--array): 9 and 6 components, and 4 only under
// OpenGeoSys's stress and strain names (sigma, epsilon), since arrays of 3 or
// 4 components are vectors and colours as often as tensors.
bool tensorLikeArray(int components, const std::string& name);
// A 2-D tensor as a full row-major 3x3: 4 components XX YY ZZ XY (as
// OpenGeoSys writes them), or 3 XX YY XY (ZZ = 0); XZ = YZ = 0.
void planarTensor(int components, const double* t, double full[9]);

// --tensor-axes (tensor/fibre_coherence.h, AxisMap): the stored tensors'
// axes read as `axes` ("-x,y,z"), composed into tensorToWC and the
// tensors; "" or "x,y,z" changes nothing. The caller has checked the name.
void applyTensorAxes(TensorField& f, const std::string& axes);

// Median nearest-neighbour distance over a sample of up to 512 points.
double estimateSampleSpacing(std::span<const float> positions);

}  // namespace tg::io
