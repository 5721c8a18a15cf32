#include <sys/stat.h>

#include <algorithm>

#include "io/readers.h"

namespace tg::io {

TensorField readTensorField(const std::string& path, const ReadOptions& opt) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) throw InputError("readTensorField: " + path + ": no such file");
  if (S_ISDIR(st.st_mode)) throw InputError("readTensorField: " + path + ": is a directory");
  if (!S_ISREG(st.st_mode)) throw InputError("readTensorField: " + path + ": not a regular file");
  if (st.st_size == 0) throw InputError("readTensorField: " + path + ": file is empty");
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const auto dot = lower.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : lower.substr(dot + 1);
  if (ext == "vtk" || ext == "vti" || ext == "vtu" || ext == "vtp" || ext == "vts") return readVtk(path, opt);
  if (ext == "nrrd" || ext == "nhdr") return readNrrd(path, opt);
  if (ext == "nii" || lower.ends_with(".nii.gz")) return readNifti(path, opt);
  if (ext == "mif" || ext == "mih") return readMif(path, opt);
  throw InputError("readTensorField: " + path + ": unknown extension \"" + (ext.empty() ? "" : "." + ext) +
                   "\"; supported: .nrrd .nhdr .nii .nii.gz .mif .mih .vtk .vti .vtu .vtp .vts");
}

}  // namespace tg::io
