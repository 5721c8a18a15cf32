#pragma once
// VTK, Teem and libnifti, each behind a module loaded the first time a file
// of theirs is read or written: tensorglyph-vtk.so, tensorglyph-teem.so and
// tensorglyph-nifti.so beside the binary (io/core/module_loader.h). The program
// itself links none of the three, so a command that reads no such file
// never has the dynamic loader resolve them; a file read in the guarded
// child (io/core/read_guard.h) loads its module in the child alone.
//
// Programs that link a module's objects themselves (the tests, the fuzzers:
// tg_io_linked in CMake) use them in place, without loading anything.
//
// The readers.h, writers.h, input_files.h and mesh_reader.h functions call
// through these tables; the rest of the program need not know of them.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/core/mesh_reader.h"
#include "io/core/read_guard.h"
#include "io/core/readers.h"
#include "io/core/tract_reader.h"

namespace tg::io {

struct VtkFormats {
  static constexpr int kVersion = 3;
  int version;
  TensorField (*readVtk)(const std::string& path, const ReadOptions& opt);
  void (*checkLegacyHeader)(const std::string& path);
  void (*checkXmlHeader)(const std::string& path);
  ScalarVolume (*readVtiScalar)(const std::string& path, const int* dims);
  // readMesh's work, in whichever process calls it; `promise` may be empty.
  MeshData (*readMesh)(const std::string& path, MeshSource source, std::uint64_t memoryBudget,
                       const PromiseFn& promise);
  // readTracts's work on a .vtk or .vtp's polylines; `promise` may be empty.
  TractData (*readTracts)(const std::string& path, std::uint64_t memoryBudget, const PromiseFn& promise);
  // The bytes writeVtk puts in `path` (its extension chooses the format).
  std::string (*encodeVtk)(const TensorField& f, const std::string& path);
};

struct TeemFormats {
  static constexpr int kVersion = 2;
  int version;
  TensorField (*readNrrd)(const std::string& path, const ReadOptions& opt);
  ScalarVolume (*readNrrdScalar)(const std::string& path, const int* dims);
  std::vector<std::string> (*nrrdDataFiles)(const std::string& header);
  // writeNrrd's file, written to the open file `fd` standing for `path`;
  // returns its size.
  std::int64_t (*writeNrrd)(const TensorField& f, const std::string& path, int fd, const double frame[9]);
  // A detached header for `count` float tensors (6 values each, xx xy xz yy
  // yz zz) on the grid `dims`, spacing 1, whose data is the file `dataFile`
  // beside it; written to `fd` standing for `path`; returns its size.
  // Errors begin with `caller`.
  std::int64_t (*writeRawTensorHeader)(const std::string& path, int fd, const std::size_t dims[3],
                                       const std::string& dataFile, const std::string& caller);
};

struct NiftiFormats {
  static constexpr int kVersion = 2;
  int version;
  TensorField (*readNifti)(const std::string& path, const ReadOptions& opt);
  ScalarVolume (*readNiftiScalar)(const std::string& path, const int* dims);
};

// The tables, linked in or loaded once. Throw ModuleError (io/core/module_loader.h)
// "<who>: <path>: needs VTK, through the module DIR/tensorglyph-vtk.so,
// which is missing".
const VtkFormats& vtkFormats(const std::string& who, const std::string& path);
const TeemFormats& teemFormats(const std::string& who, const std::string& path);
const NiftiFormats& niftiFormats(const std::string& who, const std::string& path);

}  // namespace tg::io

// The modules' entry points.
extern "C" {
const tg::io::VtkFormats* tg_vtk_formats();
const tg::io::TeemFormats* tg_teem_formats();
const tg::io::NiftiFormats* tg_nifti_formats();
}
