#pragma once
// Tensor field writers, used by the synthetic data generator.
#include <string>

#include "io/field/tensor_field.h"

namespace tg::io {

// .vtk (legacy binary), .vti (needs f.grid; Direction written), .vtu, .vtp.
// Point tensors are written as 9-component "tensors".
void writeVtk(const TensorField& f, const std::string& path);

// A gridded field as NRRD through Teem: kind 3D-symmetric-matrix (6 values,
// xx xy xz yy yz zz), space "right-anterior-superior", space directions and
// origin from f.grid, and the measurement frame `frame` (row-major 3x3, column
// k = axis k of the measurement frame in world space). Tensors are stored in
// that frame, D_stored = Mᵀ D_world M, as scanners write them.
void writeNrrd(const TensorField& f, const std::string& path, const double frame[9]);

}  // namespace tg::io
