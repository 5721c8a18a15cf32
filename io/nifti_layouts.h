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
// component-major: component c of voxel v at c * voxels + v.
std::string implausibleLayoutWarning(const std::vector<float>& values, std::size_t voxels, const NiftiLayout& chosen);

}  // namespace tg::io
