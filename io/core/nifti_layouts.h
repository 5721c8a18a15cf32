#pragma once
// Six-component tensor conventions: the component orders (--layout) of the
// tools that write NIfTI tensors, VTK arrays and FEM results, the tensor
// frames (--frame) of NIfTI files, and the check that a reading is plausible.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/field/tensor_field.h"

namespace tg::io {

// The axes the stored tensors are expressed in.
enum class TensorFrame {
  Voxel,  // the voxel axes i j k; rotated into the world by the affine's orthogonal part
  Fsl,    // FSL's voxel axes: as Voxel, but with i reversed when the affine's det > 0
  World,  // the world (scanner, RAS) axes of the affine: not rotated
};

// The inputs a layout applies to: the bits of NiftiLayout::inputs.
enum LayoutInput : unsigned { kNiftiInput = 1u, kVtkInput = 2u, kArrayInput = 4u };

// One row per --layout name (and Python's layout=): the one table the
// readers, the CLI's help and check, `info` and the Python module read.
struct NiftiLayout {
  const char* name;         // as --layout takes it
  std::array<int, 6> sym;   // value index of xx xy xz yy yz zz
  TensorFrame frame;        // the frame its writers use: --frame's default (NIfTI, array volumes)
  const char* order;        // the stored order, for messages
  unsigned inputs;          // LayoutInput bits: where the name is accepted
};

// Null: unknown, or not for `input` (any of its bits).
const NiftiLayout* niftiLayoutNamed(std::string_view name, unsigned input = kNiftiInput | kVtkInput | kArrayInput);
const std::vector<NiftiLayout>& niftiLayouts();
// "fsl, nifti, mrtrix, vtk or paraview": the names for `input`, for messages.
std::string layoutChoices(unsigned input);
// Why `name` cannot be read for `input` (called `inputName` in the message):
// unknown, or not for it; both list the names that are.
std::string unusableLayout(std::string_view name, unsigned input, const char* inputName);
std::optional<TensorFrame> tensorFrameNamed(std::string_view name);
const char* tensorFrameName(TensorFrame f);
inline constexpr const char* kTensorFrameChoices = "voxel, fsl or world";

// Where tensors stored in `frame` point in WC, for a volume whose index axes
// in WC are `axesWC` (row-major; column k is one step along index k), placed
// by an affine or (`fromAffine` false) by voxel sizes alone. tensorToWC is T
// in D_WC = T D Tᵀ, none for World; the description says which axes, for
// `info`. The caller refuses a singular `axesWC` first.
struct FrameMap {
  std::optional<std::array<double, 9>> tensorToWC;
  std::string description;
};
FrameMap tensorFrameMap(TensorFrame frame, const double axesWC[9], bool fromAffine);
// The frames other than `applied` whose map differs from its map here (fsl
// and voxel agree where det < 0), for TensorField::otherFrames.
std::vector<FrameChoice> otherFrames(TensorFrame applied, const double axesWC[9], bool fromAffine);

// Whether a reading of the six stored values is plausible. A reading is
// the tensors one layout makes of them. Two criteria, each applying to some
// inputs, with a gap between "plausible" and "implausible" where nothing is
// offered or refused:
//  - diffusion (NIfTI, array volumes, points in the default order): a
//    tensor is indefinite when a principal minor is below -1% of its largest
//    component (to the minor's power); a reading is plausible when at most a
//    fifth of the sampled tensors are (positive semi-definite within noise;
//    DIPY's small_64D fit: 0 of 1000), implausible when more than half are;
//  - plane (points lying in a coordinate plane: a plate, a 2-D model, a free
//    surface): a tensor has out-of-plane shear when one is above 1e-3 of the
//    sample's largest component; plausible when at most 1% have, implausible
//    when more than 10% have. Plane stress and plane strain have none; a
//    wrong order moves in-plane values there.
// With no criterion nothing can tell: a stress field may be indefinite.
struct Plausibility {
  bool diffusion = false;
  int planeNormal = -1;  // 0, 1, 2: the axis the points do not extend along; -1: none
};
// The axis along which the bounds [lo, hi] have no extent while the other two
// have (relative to the largest, 1e-6), or -1.
int coordinatePlaneNormal(const double lo[3], const double hi[3]);

// Up to ~16384 tensors' six stored values, spread evenly; all-zero
// (background) and non-finite ones say nothing about the order and are left out.
class LayoutSample {
 public:
  explicit LayoutSample(std::uint64_t count);
  void offer(std::uint64_t index, const double v[6]);
  // Component-major values (component c of voxel v at c * voxels + v), as
  // the NIfTI reader keeps them.
  static LayoutSample ofComponents(const std::vector<float>& values, std::size_t voxels);
  const std::vector<double>& rows() const { return rows_; }

 private:
  std::uint64_t step_;
  std::vector<double> rows_;
};

// How to name a layout to the user: "--layout nifti --frame voxel" or
// "layout=\"nifti\"".
using LayoutNamer = std::string (*)(const NiftiLayout&);
std::string cliLayoutName(const NiftiLayout& l);         // --layout NAME
std::string cliNiftiLayoutName(const NiftiLayout& l);    // --layout NAME --frame FRAME
std::string pythonLayoutName(const NiftiLayout& l);      // layout="NAME"

// The verdict on reading the sample in `chosen`, among the layouts for
// `input`. Refused (refusal set, warning empty) when `chosen` was the
// default, fails a criterion, and exactly one other reading (one or more
// names that give the same tensors here) passes: drawing the implausible one
// would be a guess against the evidence. With `refuseUnexplained` also when no
// other reading passes. Otherwise a failed criterion is a warning, which
// names only readings that pass. Both empty: plausible, or nothing can tell.
struct LayoutAdvice {
  std::string warning, refusal;
};
LayoutAdvice adviseLayout(const LayoutSample& sample, const NiftiLayout& chosen, bool byDefault, unsigned input,
                          const Plausibility& criteria, LayoutNamer name, bool refuseUnexplained = false);

}  // namespace tg::io
