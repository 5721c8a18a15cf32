#pragma once
// Format readers. Each validates its header before allocating from it, and
// throws InputError with a one-line message naming the file and the problem.
#include <string>

#include "io/tensor_field.h"

namespace tg::io {

struct ReadOptions {
  std::string arrayName;  // empty: the active tensors, else the only 6/9-component array
};

// Legacy .vtk and XML .vti/.vtu/.vtp/.vts through VTK's readers.
TensorField readVtk(const std::string& path, const ReadOptions& opt);

// Any supported file, by extension. Checks existence, type and emptiness first.
TensorField readTensorField(const std::string& path, const ReadOptions& opt);

}  // namespace tg::io
