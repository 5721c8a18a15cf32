#pragma once
// Format readers. Each validates its header before allocating from it, and
// throws InputError with a one-line message naming the file and the problem.
#include <cstdint>
#include <functional>
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
  // Memory the load may take (0: no limit); readers refuse a header whose
  // promised data would exceed it before allocating anything.
  std::uint64_t memoryBudget = 0;
  // Set by readTensorField's child process: told the decoded bytes and the
  // memory a read will take once its reader knows them (io/read_guard.h).
  std::function<void(std::uint64_t decodedBytes, std::uint64_t memoryBytes)> onPromise;
};

// Bytes one kept tensor takes at the peak of a load: its sample (position,
// tensor, id: 40 B) while its glyph record (48 B) is built, rounded up.
inline constexpr std::uint64_t kPeakBytesPerTensor = 96;

// Called by each reader once its header is checked and before any data is
// decoded. The memory the read will take is `keptSamples` tensors plus
// `libraryBytes` that a library holds while it parses (VTK's whole dataset);
// beyond opt.memoryBudget it throws InputError naming `who` and `path`. Else
// decodedBytes and that memory go on to opt.onPromise.
void promiseData(const char* who, const std::string& path, const ReadOptions& opt, std::uint64_t decodedBytes,
                 std::uint64_t keptSamples, std::uint64_t libraryBytes = 0);

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

// Scalar volumes, for masks: refused before any data is decoded unless their
// grid is `dims`.
ScalarVolume readNrrdScalar(const std::string& path, const int dims[3]);
ScalarVolume readNiftiScalar(const std::string& path, const int dims[3]);
ScalarVolume readVtiScalar(const std::string& path, const int dims[3]);

// Any supported file, by extension. Checks existence, type and emptiness
// first, then reads in a child process under limits (io/read_guard.h), with
// opt.memoryBudget defaulting to defaultMemoryBudget().
TensorField readTensorField(const std::string& path, const ReadOptions& opt);
// The same without the child process: for fuzzing and the load benchmark.
TensorField readTensorFieldInProcess(const std::string& path, const ReadOptions& opt);

}  // namespace tg::io
