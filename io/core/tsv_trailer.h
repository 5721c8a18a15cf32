#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "io/field/tensor_field.h"

namespace tg::io {

// The stresses of a 3D-TSV legacy .vtk file's "Cartesian Stress" trailer as
// row-major 3x3 tensors, one per point. False when the file has no trailer;
// InputError when it has a malformed one.
bool readTsvStressTrailer(const std::string& path, std::uint64_t points, std::vector<double>& full9);

}  // namespace tg::io
