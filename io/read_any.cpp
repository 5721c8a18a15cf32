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
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == "vtk" || ext == "vti" || ext == "vtu" || ext == "vtp" || ext == "vts") return readVtk(path, opt);
  throw InputError("readTensorField: " + path + ": unknown extension \"" + (ext.empty() ? "" : "." + ext) +
                   "\"; supported: .vtk .vti .vtu .vtp .vts");
}

}  // namespace tg::io
