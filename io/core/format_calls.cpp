// The format functions of readers.h, writers.h, input_files.h and
// mesh_reader.h, called through the VTK, Teem and NIfTI modules
// (io/core/format_modules.h). Output files are made here, by AtomicFile, so that
// their temporary files are those this process's signal handlers know of
// (io/field/temp_registry.h); the modules only encode.
#include "io/field/atomic_file.h"
#include "io/core/format_modules.h"
#include "io/core/format_table.h"
#include "io/core/input_files.h"
#include "io/core/module_loader.h"
#include "io/core/writers.h"

// Weak: defined only where a module's objects are linked into the program.
extern "C" {
__attribute__((weak)) const tg::io::VtkFormats* tg_vtk_formats();
__attribute__((weak)) const tg::io::TeemFormats* tg_teem_formats();
__attribute__((weak)) const tg::io::NiftiFormats* tg_nifti_formats();
}

namespace tg::io {
namespace {

template <class Table>
const Table& formats(const Table* (*linked)(), const LoadedModule& loaded, const std::string& who,
                     const std::string& path, const char* library) {
  if (linked) return *linked();
  if (!loaded.table) throwModuleError(who, path, library, loaded);
  return *static_cast<const Table*>(loaded.table);
}

}  // namespace

// Each module is loaded once per process; its handle stays open until exit.
// Linked in (the weak symbol defined), it needs no loading.
const LoadedModule& vtkModule() {
  static const LoadedModule loaded =
      tg_vtk_formats ? LoadedModule{} : loadModule("tensorglyph-vtk.so", "tg_vtk_formats", VtkFormats::kVersion);
  return loaded;
}
const LoadedModule& teemModule() {
  static const LoadedModule loaded = tg_teem_formats
                                         ? LoadedModule{}
                                         : loadModule("tensorglyph-teem.so", "tg_teem_formats", TeemFormats::kVersion);
  return loaded;
}
const LoadedModule& niftiModule() {
  static const LoadedModule loaded =
      tg_nifti_formats ? LoadedModule{}
                       : loadModule("tensorglyph-nifti.so", "tg_nifti_formats", NiftiFormats::kVersion);
  return loaded;
}

const VtkFormats& vtkFormats(const std::string& who, const std::string& path) {
  return formats(tg_vtk_formats, vtkModule(), who, path, "VTK");
}
const TeemFormats& teemFormats(const std::string& who, const std::string& path) {
  return formats(tg_teem_formats, teemModule(), who, path, "Teem");
}
const NiftiFormats& niftiFormats(const std::string& who, const std::string& path) {
  return formats(tg_nifti_formats, niftiModule(), who, path, "libnifti");
}

std::string moduleProblem(std::string_view module) {
  const auto problem = [](bool linked, const LoadedModule& m) {
    return linked || m.table ? std::string() : m.path + " " + m.error;
  };
  if (module == "vtk") return problem(tg_vtk_formats, vtkModule());
  if (module == "teem") return problem(tg_teem_formats, teemModule());
  if (module == "nifti") return problem(tg_nifti_formats, niftiModule());
  if (module.empty()) return {};
  return "no module named \"" + std::string(module) + "\"";
}

TensorField readVtk(const std::string& path, const ReadOptions& opt) {
  return vtkFormats("readVtk", path).readVtk(path, opt);
}
void checkVtkLegacyHeader(const std::string& path) { vtkFormats("readVtk", path).checkLegacyHeader(path); }
void checkVtkXmlHeader(const std::string& path) { vtkFormats("readVtk", path).checkXmlHeader(path); }
ScalarVolume readVtiScalar(const std::string& path, const int dims[3]) {
  return vtkFormats("readVtk", path).readVtiScalar(path, dims);
}
MeshData readMeshInProcess(const std::string& path, MeshSource source, std::uint64_t memoryBudget) {
  return vtkFormats("readMesh", path).readMesh(path, source, memoryBudget, nullptr);
}

void writeVtk(const TensorField& f, const std::string& path) {
  const std::string bytes = vtkFormats("writeVtk", path).encodeVtk(f, path);
  AtomicFile out(path);
  out.write(bytes.data(), bytes.size());
  out.commit(std::int64_t(bytes.size()));
}

TensorField readNrrd(const std::string& path, const ReadOptions& opt) {
  return teemFormats("readNrrd", path).readNrrd(path, opt);
}
ScalarVolume readNrrdScalar(const std::string& path, const int dims[3]) {
  return teemFormats("readNrrd", path).readNrrdScalar(path, dims);
}
std::vector<std::string> nrrdDataFiles(const std::string& header) {
  return teemFormats("nrrdDataFiles", header).nrrdDataFiles(header);
}

void writeNrrd(const TensorField& f, const std::string& path, const double frame[9]) {
  const TeemFormats& teem = teemFormats("writeNrrd", path);
  AtomicFile out(path);
  out.commit(teem.writeNrrd(f, path, out.fd(), frame));
}

TensorField readNifti(const std::string& path, const ReadOptions& opt) {
  return niftiFormats("readNifti", path).readNifti(path, opt);
}
ScalarVolume readNiftiScalar(const std::string& path, const int dims[3]) {
  return niftiFormats("readNifti", path).readNiftiScalar(path, dims);
}

}  // namespace tg::io
