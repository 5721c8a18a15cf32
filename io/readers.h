#pragma once
// Format readers. Each validates its header before allocating from it, and
// throws InputError with a one-line message naming the file and the problem.
#include <string>

#include "io/selection.h"
#include "io/tensor_field.h"

namespace tg::io {

struct ReadOptions {
  std::string arrayName;  // VTK: empty: the active tensors, else the only 6/9-component array
  // NIfTI component order: "" (auto: the SYMMATRIX intent means "nifti",
  // else "fsl"), "fsl", "nifti", "mrtrix" or "vtk". See readNifti.
  std::string layout;
  Selection selection;
};

// Legacy .vtk and XML .vti/.vtu/.vtp/.vts through VTK's readers.
TensorField readVtk(const std::string& path, const ReadOptions& opt);
// The header path of a legacy .vtk alone: the count checks readVtk makes
// before VTK allocates anything, and VTK's own header and dataset-type read.
void checkVtkLegacyHeader(const std::string& path);

// .nrrd/.nhdr through Teem: kinds 3D-symmetric-matrix, 3D-masked-symmetric-
// matrix and 3D-matrix on the first axis; space directions or old axis
// mins/maxs/spacings; the measurement frame; LPS and LAS turned into RAS.
TensorField readNrrd(const std::string& path, const ReadOptions& opt);

// .nii/.nii.gz (NIfTI-1 and -2) through libnifti2: six volumes along the 4th
// or 5th dimension. Placement from the sform, else the qform, else pixdim.
// Tensor frame by layout: "fsl" tensors are in FSL's voxel frame (x mirrored
// when the affine's determinant is positive), "nifti" and "vtk" in the voxel
// frame; both are rotated into the world by the affine's orthogonal part.
// "mrtrix" tensors are already in the world (scanner) frame.
TensorField readNifti(const std::string& path, const ReadOptions& opt);
// The --layout names readNifti knows, for checking a command line early.
bool isNiftiLayout(const std::string& name);
inline constexpr const char* kNiftiLayoutChoices = "fsl, nifti, mrtrix or vtk";

// MRtrix .mif (header and data) and .mih (header naming a data file), read by
// hand: a 4-D image whose last axis holds xx yy zz xy xz yz, tensors already
// in scanner space (as dwi2tensor writes them), placed at
// transform * (ijk .* vox) in RAS. Any layout (strides), data type and byte
// order; scaling applied. --layout other than "mrtrix" is refused.
TensorField readMif(const std::string& path, const ReadOptions& opt);

// Scalar volumes, for masks.
ScalarVolume readNrrdScalar(const std::string& path);
ScalarVolume readNiftiScalar(const std::string& path);
ScalarVolume readVtiScalar(const std::string& path);
ScalarVolume readMifScalar(const std::string& path);

// Any supported file, by extension. Checks existence, type and emptiness first.
TensorField readTensorField(const std::string& path, const ReadOptions& opt);

}  // namespace tg::io
