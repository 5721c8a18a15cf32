#pragma once
// What the module takes from NumPy: views of tensor and position arrays,
// and underlay and mask volumes given in memory (python/module.cpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>

#include "io/core/array_field.h"
#include "io/core/selection.h"

namespace tg::python {

namespace py = pybind11;

// underlay= and mask= given in memory (an array, a nibabel image): the
// values i fastest, the grid, and where it lies when an affine came with it
// (none: on the tensors' grid). None gives null.
std::shared_ptr<const io::ScalarVolume> scalarVolume(const py::handle& given, const char* kw);

// Equal values, grid and placement (null equals only null).
bool sameVolume(const std::shared_ptr<const io::ScalarVolume>& a, const std::shared_ptr<const io::ScalarVolume>& b);

// A view of `a`'s float values, with the GIL held: it is read later without it.
io::ArrayRef arrayRef(const py::array& a, const char* arg);

}  // namespace tg::python
