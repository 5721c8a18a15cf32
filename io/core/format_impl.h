#pragma once
// What the VTK, Teem and NIfTI modules implement (io/core/format_modules.h): the
// entries of their tables. The rest of the program calls the functions of
// readers.h, writers.h and mesh_reader.h instead, which find the module.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "io/core/format_modules.h"

namespace tg::io::impl {

// tensorglyph-vtk.so: io/modules/vtk/vtk_reader.cpp, io/modules/vtk/mesh_reader.cpp, io/modules/vtk/vtk_writer.cpp.
TensorField readVtk(const std::string& path, const ReadOptions& opt);
void checkVtkLegacyHeader(const std::string& path);
void checkVtkXmlHeader(const std::string& path);
ScalarVolume readVtiScalar(const std::string& path, const int* dims);
MeshData readMesh(const std::string& path, MeshSource source, std::uint64_t memoryBudget, const PromiseFn& promise);
TractData readPolylines(const std::string& path, std::uint64_t memoryBudget, const PromiseFn& promise);
std::string encodeVtk(const TensorField& f, const std::string& path);

// tensorglyph-teem.so: io/modules/teem/nrrd_reader.cpp, io/modules/teem/nrrd_files.cpp, io/modules/teem/nrrd_writer.cpp.
TensorField readNrrd(const std::string& path, const ReadOptions& opt);
ScalarVolume readNrrdScalar(const std::string& path, const int* dims);
std::vector<std::string> nrrdDataFiles(const std::string& header);
// The header text before Teem parses it: at most 4096 key:=value pairs and
// comment lines, no field line longer than 512 bytes (Teem's error messages
// overflow a stack buffer on longer ones), no line beyond 1 MiB and no
// header beyond 16 MiB. `in` is left at its start.
void checkNrrdHeaderText(const char* who, const std::string& path, FILE* in);
// What nrrdDataFiles refuses in a header Teem can parse (a data file range or
// format too long to step through): readNrrd says so before Teem opens any.
struct NrrdDataFilesRefused : InputError {
  using InputError::InputError;
};
std::int64_t writeNrrd(const TensorField& f, const std::string& path, int fd, const double frame[9]);
std::int64_t writeRawTensorHeader(const std::string& path, int fd, const std::size_t dims[3],
                                  const std::string& dataFile, const std::string& caller);

// tensorglyph-nifti.so: io/modules/nifti/nifti_reader.cpp.
TensorField readNifti(const std::string& path, const ReadOptions& opt);
ScalarVolume readNiftiScalar(const std::string& path, const int* dims);

}  // namespace tg::io::impl
