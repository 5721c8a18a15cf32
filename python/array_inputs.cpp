#include "python/array_inputs.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/stl.h>

namespace tg::python {

std::shared_ptr<const io::ScalarVolume> scalarVolume(const py::handle& given, const char* kw) {
  if (given.is_none()) return nullptr;
  const auto t = given.cast<py::tuple>();
  auto values = t[0].cast<py::array_t<float, py::array::c_style | py::array::forcecast>>();
  const auto dims = t[1].cast<std::vector<long long>>();
  const auto affine = t[2].cast<std::optional<std::vector<double>>>();
  auto v = std::make_shared<io::ScalarVolume>();
  std::uint64_t voxels = 1;
  if (dims.size() != 3) throw std::invalid_argument(std::string(kw) + ": a volume has 3 axes");
  for (int k = 0; k < 3; ++k) {
    if (dims[std::size_t(k)] < 1 || dims[std::size_t(k)] > INT32_MAX)
      throw std::invalid_argument(std::string(kw) + ": an empty or too large axis");
    v->dims[k] = int(dims[std::size_t(k)]);
    voxels *= std::uint64_t(v->dims[k]);
  }
  if (std::uint64_t(values.size()) != voxels) throw std::invalid_argument(std::string(kw) + ": values and shape differ");
  v->values.assign(values.data(), values.data() + values.size());
  if (affine) {
    if (affine->size() != 16) throw std::invalid_argument(std::string(kw) + "_affine: must be 4x4");
    v->placement = io::placementFromAffine(std::string(kw) + "_affine", affine->data());
  }
  return v;
}

bool sameVolume(const std::shared_ptr<const io::ScalarVolume>& a, const std::shared_ptr<const io::ScalarVolume>& b) {
  if (!a || !b) return a == b;
  const auto placed = [](const io::ScalarVolume& v) {
    std::vector<double> out;
    if (v.placement) {
      out.assign(v.placement->originWC, v.placement->originWC + 3);
      out.insert(out.end(), v.placement->axesWC, v.placement->axesWC + 9);
    }
    return out;
  };
  return std::equal(a->dims, a->dims + 3, b->dims) && a->values == b->values && placed(*a) == placed(*b);
}

io::ArrayRef arrayRef(const py::array& a, const char* arg) {
  io::ArrayRef r;
  r.data = a.data();
  if (a.dtype().kind() != 'f') throw std::domain_error(std::string(arg) + ": values must be float32 or float64");
  // The values are read in place: swapped bytes would be other, finite numbers.
  if (!a.dtype().attr("isnative").cast<bool>())
    throw std::domain_error(std::string(arg) + ": values must be in this machine's byte order, not " +
                            std::string(py::str(a.dtype())));
  r.itemBytes = int(a.itemsize());
  for (py::ssize_t k = 0; k < a.ndim(); ++k) {
    r.shape.push_back(a.shape(k));
    r.strides.push_back(a.strides(k));
  }
  return r;
}

}  // namespace tg::python
