#pragma once
// Tensor fields from arrays in memory: what the Python module hands over from
// NumPy, nibabel or DIPY, read with the CLI's conventions (the component
// orders and frames of io/core/nifti_layouts.h, the selection of io/core/selection.h).
// As a file's, a tensor with NaN/Inf or beyond single precision is skipped
// and counted; a NaN/Inf or overflowing position is refused. Every error is std::invalid_argument, or
// std::domain_error for a wrong dtype, beginning with the argument's name
// ("tensors: shape (4, 5) is ...").
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/core/nifti_layouts.h"
#include "io/core/readers.h"
#include "io/core/selection.h"
#include "io/field/tensor_field.h"

namespace tg::io {

// A strided view of float32 or float64 values; strides in bytes.
struct ArrayRef {
  const void* data = nullptr;
  int itemBytes = 8;  // 4: float32, 8: float64; anything else is a dtype error
  std::vector<std::int64_t> shape, strides;
};

// Points in WC: `tensors` (N, 3, 3), or (N, 6) in `layout` (a name of
// nifti_layouts.h's table; "" is FSL's order, taken only where it reads them
// as diffusion tensors: else the one order that does is named, or the
// layout asked for, in a std::invalid_argument); `positions` (N, 3).
// The tensors are in WC: a point set has no voxel axes to be in. The
// selection is a point set's, as a VTK file's points get it: stride and ROI
// apply, a slice or a mask is refused (io::Selector).
TensorField fieldFromPoints(const ArrayRef& tensors, std::string_view layout, const ArrayRef& positions,
                            const Selection& selection = {});

// The grid placement of a row-major 4x4 (nibabel's `img.affine`), refused
// (std::invalid_argument naming `arg`) unless finite, affine (last row
// 0 0 0 1) and invertible.
GridPlacement placementFromAffine(std::string_view arg, const double affine[16]);

// A volume: `tensors` (X, Y, Z, 6) in `layout` ("" FSL's, refused as a
// NIfTI file's default is: adviseLayout), or (X, Y, Z, 3, 3);
// `affine` a row-major 4x4 from voxel index (i, j, k) to WC, as nibabel's
// `img.affine`; `frame` the tensors' axes ("voxel", "fsl" or "world", as
// --frame), by default the layout's; a (…, 3, 3) volume has none, and is
// taken in the voxel axes, as DIPY's quadratic_form is. Voxels are visited i fastest, as the file readers do, so ids are
// i + X (j + Y k).
TensorField fieldFromVolume(const ArrayRef& tensors, std::string_view layout, const double affine[16],
                            std::string_view frame, const Selection& selection = {});

// The reading option that tensors from arrays have no use for, as
// inapplicableOption (io/core/readers.h) names a file format's: "--array" (only a
// VTK file names its arrays), "--confidence-min" (no confidence values); ""
// when every one applies. Layout and frame come with the arrays.
std::string inapplicableArrayOption(const ReadOptions& opt);

}  // namespace tg::io
