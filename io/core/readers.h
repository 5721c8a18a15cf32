#pragma once
// Format readers. Each validates its header before allocating from it, and
// throws InputError with a one-line message naming the file and the problem.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "io/core/selection.h"
#include "io/field/tensor_field.h"
#include "util/progress.h"

namespace tg::io {

struct RawSamples;

// Options that apply to one format only are refused by the other readers.
struct ReadOptions {
  // VTK: the point array holding the tensors; empty: the active tensors, else
  // the only tensor-like array (see readVtk).
  std::string arrayName;
  // VTK: a scalar point array to colour by (--color-array), read beside the
  // tensors into TensorField::colorValues; other formats leave it to the caller.
  std::string colorArray;
  // Component order of six values (NIfTI, 6-component VTK arrays): "" (a
  // NIfTI file's header: the SYMMATRIX intent means "nifti", an MRtrix
  // `descrip` "mrtrix", else "fsl"; VTK's own order) or a name of
  // nifti_layouts.h's table that applies to the input.
  std::string layout;
  // NIfTI tensor frame: "" (the layout's own), "voxel", "fsl" or "world".
  std::string frame;
  // --tensor-axes: the stored tensors' axes as a signed permutation
  // ("-x,y,z"; tensor/axis_map.h), for every format; "": as stored.
  std::string tensorAxes;
  Selection selection;
  // Memory the load may take (0: no limit); readers refuse a header whose
  // promised data would exceed it before allocating anything.
  std::uint64_t memoryBudget = 0;
  // Set by readTensorField's child process: told the decoded bytes and the
  // memory a read will take once its reader knows them (io/core/read_guard.h).
  std::function<void(std::uint64_t decodedBytes, std::uint64_t memoryBytes)> onPromise;
  // --confidence-min was given: the CLI refuses it for tensors without a
  // confidence value (TensorField::hasConfidence).
  bool confidenceGiven = false;
  // Set by readTensorField's child process: a volume reader whose data is
  // uncompressed and selected without a mask describes it here and returns
  // the field without samples; the parent reads them (io/core/raw_samples.h).
  std::optional<RawSamples>* deferRaw = nullptr;
  // Told how far readTensorField's child has read (io/core/read_guard.h); empty: nothing is measured.
  util::ProgressSink progress;
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

// Legacy .vtk and XML .vti/.vtu/.vtp/.vts through VTK's readers. Point
// tensors of 9 (row-major) or 6 (XX YY ZZ XY YZ XZ, or --layout's) components, or 2-D FEM
// tensors of 4 (XX YY ZZ XY, OpenGeoSys) or 3 (XX YY XY) with zero
// out-of-plane shear. Without --array: the active tensors, else the one
// array of 9 or 6 components or a 4-component OpenGeoSys `sigma`/`epsilon`;
// several such arrays are refused, named. 3-component arrays (vectors and
// colours as often) are read only when --array names them. Tensors are taken
// to be in the world axes of the points, as VTK's filters take them.
TensorField readVtk(const std::string& path, const ReadOptions& opt);
// The header path of a legacy .vtk alone: the count checks readVtk makes
// before VTK allocates anything, and VTK's own header and dataset-type read.
void checkVtkLegacyHeader(const std::string& path);
// The same for an XML .vtu: VTK's XML parse of the structure (expat) and our
// checks of it (io/modules/vtk/vtk_xml_checks.h), without decoding the data.
void checkVtkXmlHeader(const std::string& path);

// .nrrd/.nhdr through Teem: kinds 3D-symmetric-matrix, 3D-masked-symmetric-
// matrix and 3D-matrix on the first axis; space directions or old axis
// mins/maxs/spacings; the measurement frame; LPS and LAS turned into RAS.
TensorField readNrrd(const std::string& path, const ReadOptions& opt);

// .nii/.nii.gz (NIfTI-1 and -2) through libnifti2: six volumes along the 4th
// or 5th dimension. Placement from the sform, else the qform, else pixdim.
// Component order by --layout, tensor frame by --frame, each defaulting as
// nifti_layouts.h says. Refuses a default order that reads most tensors as
// indefinite when exactly one other order reads them as diffusion tensors;
// else warns, naming only orders that do (adviseLayout).
TensorField readNifti(const std::string& path, const ReadOptions& opt);
// Whether any input takes --layout `name` (io/core/nifti_layouts.h), for checking
// a command line early; each reader refuses the names its input has no use for.
bool isLayoutName(const std::string& name);

// MRtrix .mif (header and data) and .mih (header naming a data file), read by
// hand: a 4-D image whose last axis holds xx yy zz xy xz yz, tensors already
// in scanner space (as dwi2tensor writes them), placed at
// transform * (ijk .* vox) in RAS. Any layout (strides), data type and byte
// order; scaling applied. --layout other than "mrtrix" is refused.
TensorField readMif(const std::string& path, const ReadOptions& opt);
// The file a .mif/.mih header's data is in (the header itself for a .mif),
// without opening it.
std::string mifDataFile(const std::string& path);

// Scalar volumes, for masks: refused before any data is decoded unless their
// grid is `dims`. dims null (underlays): any grid that fits in memory.
ScalarVolume readNrrdScalar(const std::string& path, const int dims[3]);
ScalarVolume readNiftiScalar(const std::string& path, const int dims[3]);
ScalarVolume readVtiScalar(const std::string& path, const int dims[3]);
ScalarVolume readMifScalar(const std::string& path, const int dims[3]);

// `--underlay FILE`: a scalar volume on any grid (NRRD, NIfTI, MRtrix or
// .vti), read in a child process (io/core/read_guard.h). Refuses a file that does
// not say where its voxels lie (it could not be lined up with the tensors)
// and one without a finite value. Non-finite values stay: they are holes.
ScalarVolume readUnderlay(const std::string& path);

// The format a path names, by its extension.
enum class InputFormat { Vtk, Nrrd, Nifti, Mif, Unknown };
InputFormat inputFormatOf(const std::string& path);
const char* inputFormatName(InputFormat f);
// The flag of the first option set in `opt` that `format` has no use for
// ("--layout"), or "". Readers refuse such options rather than ignore them.
std::string inapplicableOption(InputFormat format, const ReadOptions& opt);

// Any supported file, by extension. Checks existence, type and emptiness
// first, then reads in a child process under limits (io/core/read_guard.h), with
// opt.memoryBudget defaulting to defaultMemoryBudget().
TensorField readTensorField(const std::string& path, const ReadOptions& opt);
// The same without the child process: for fuzzing and the load benchmark.
TensorField readTensorFieldInProcess(const std::string& path, const ReadOptions& opt);

}  // namespace tg::io
