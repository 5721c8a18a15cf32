#pragma once
// NIfTI tensor conventions: the component orders (--layout) and tensor frames
// (--frame) that the tools writing tensor NIfTI files use, and the check that
// a reading is plausible for diffusion tensors.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tg::io {

// The axes the stored tensors are expressed in.
enum class TensorFrame {
  Voxel,  // the voxel axes i j k; rotated into the world by the affine's orthogonal part
  Fsl,    // FSL's voxel axes: as Voxel, but with i reversed when the affine's det > 0
  World,  // the world (scanner, RAS) axes of the affine: not rotated
};

struct NiftiLayout {
  const char* name;         // as --layout takes it
  std::array<int, 6> sym;   // value index of xx xy xz yy yz zz
  TensorFrame frame;        // the frame its writers use: --frame's default
  const char* order;        // the stored order, for messages
};

const NiftiLayout* niftiLayoutNamed(std::string_view name);  // null: unknown
const std::vector<NiftiLayout>& niftiLayouts();
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

// How many of up to `maxSamples` non-zero voxels, spread evenly over the
// `voxels` voxels of `values` (six per voxel, in file order), are not
// positive semi-definite when read in order `sym`. A rotation or mirror of
// the frame cannot change this; only the component order can.
struct Definiteness {
  std::size_t sampled = 0, indefinite = 0;
};
Definiteness definiteness(const std::vector<float>& values, std::size_t voxels, const std::array<int, 6>& sym,
                          std::size_t maxSamples = 4096);

// "" when most sampled tensors are positive semi-definite under `chosen`;
// else one line saying how many are not, naming the layouts (and their
// frames) that read most of them as positive semi-definite. `values` are
// component-major: component c of voxel v at c * voxels + v. With
// `onlyIfAnotherFits`, "" also when no other layout does better: tensors
// that may be indefinite (stress, arrays from any source) are no evidence of
// a wrong order by themselves.
std::string implausibleLayoutWarning(const std::vector<float>& values, std::size_t voxels, const NiftiLayout& chosen,
                                     bool onlyIfAnotherFits = false);

}  // namespace tg::io
