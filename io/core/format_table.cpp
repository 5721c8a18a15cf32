#include "io/core/format_table.h"

#include <sys/stat.h>

#include <algorithm>

#include "io/core/input_files.h"

namespace tg::io {
namespace {

// A .mih header's data file; a .mif holds its own (mifDataFile names the
// header itself). A header the reader will refuse names no file to protect.
std::vector<std::string> mifDataFiles(const std::string& path) {
  try {
    std::string data = mifDataFile(path);
    if (data != path) return {std::move(data)};
  } catch (const InputError&) {
  }
  return {};
}

std::string lowered(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

}  // namespace

const std::vector<InputFormatRow>& inputFormats() {
  // NRRD and MRtrix state their own component order and frame (kind and
  // measurement frame; MRtrix's in scanner space); NIfTI leaves both to
  // convention, and a 6-component VTK array its order (VTK's own by default,
  // but FEM codes write theirs), in world axes. Only VTK has named arrays;
  // only NRRD has confidence.
  static const std::vector<InputFormatRow> rows = {
      {InputFormat::Nrrd, "NRRD", {".nrrd", ".nhdr"}, kTensorUse | kScalarUse, kConfidenceOption, "teem", readNrrd,
       "readNrrd", readNrrdScalar, nrrdDataFiles},
      {InputFormat::Nifti, "NIfTI", {".nii", ".nii.gz"}, kTensorUse | kScalarUse, kLayoutOption | kFrameOption,
       "nifti", readNifti, "readNifti", readNiftiScalar, nullptr},
      {InputFormat::Mif, "MRtrix", {".mif", ".mih"}, kTensorUse | kScalarUse, 0, "", readMif, "readMif",
       readMifScalar, mifDataFiles},
      {InputFormat::Vtk, "VTK", {".vtk"}, kTensorUse | kSurfaceUse | kFemUse | kTractUse, kLayoutOption | kArrayOption, "vtk",
       readVtk, "readVtk", nullptr, nullptr},
      {InputFormat::Vtk, "VTK", {".vti"}, kTensorUse | kScalarUse, kLayoutOption | kArrayOption, "vtk", readVtk,
       "readVtk", readVtiScalar, nullptr},
      {InputFormat::Vtk, "VTK", {".vtu"}, kTensorUse | kVolumeMeshUse | kFemUse, kLayoutOption | kArrayOption, "vtk",
       readVtk, "readVtk", nullptr, nullptr},
      {InputFormat::Vtk, "VTK", {".vtp"}, kTensorUse | kSurfaceUse | kTractUse, kLayoutOption | kArrayOption, "vtk", readVtk,
       "readVtk", nullptr, nullptr},
      {InputFormat::Vtk, "VTK", {".vts"}, kTensorUse | kVolumeMeshUse, kLayoutOption | kArrayOption, "vtk", readVtk,
       "readVtk", nullptr, nullptr},
      {InputFormat::Unknown, "STL", {".stl"}, kSurfaceUse, 0, "vtk"},
      {InputFormat::Unknown, "OBJ", {".obj"}, kSurfaceUse, 0, "vtk"},
      {InputFormat::Unknown, "PLY", {".ply"}, kSurfaceUse, 0, "vtk"},
      {InputFormat::Unknown, "MRtrix tracks", {".tck"}, kTractUse, 0, ""},
      {InputFormat::Unknown, "TrackVis", {".trk"}, kTractUse, 0, ""},
  };
  return rows;
}

const InputFormatRow* inputFormatRowOf(const std::string& path) {
  const std::string lower = lowered(path);
  const InputFormatRow* best = nullptr;
  std::size_t bestLength = 0;
  // The longest match: ".nii.gz" is NIfTI whatever a ".gz" row would say.
  for (const InputFormatRow& row : inputFormats())
    for (const std::string& ext : row.extensions)
      if (ext.size() > bestLength && lower.ends_with(ext)) {
        best = &row;
        bestLength = ext.size();
      }
  return best;
}

std::string extensionList(unsigned uses, const std::string& sep, const std::string& lastSep) {
  std::vector<std::string> all;
  for (const InputFormatRow& row : inputFormats())
    if (row.uses & uses) all.insert(all.end(), row.extensions.begin(), row.extensions.end());
  std::string out;
  for (std::size_t k = 0; k < all.size(); ++k)
    out += (k == 0 ? "" : k + 1 == all.size() && !lastSep.empty() ? lastSep : sep) + all[k];
  return out;
}

std::string shownExtension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  return dot == std::string::npos || path.find('/', dot) != std::string::npos ? "" : path.substr(dot);
}

std::uint64_t checkInputFile(const std::string& who, const std::string& path) {
  auto fail = [&](const char* what) { return InputError(who + ": " + path + ": " + what); };
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw fail("no such file");
  if (S_ISDIR(st.st_mode)) throw fail("is a directory");
  if (!S_ISREG(st.st_mode)) throw fail("not a regular file");
  if (st.st_size == 0) throw fail("file is empty");
  return std::uint64_t(st.st_size);
}

}  // namespace tg::io
