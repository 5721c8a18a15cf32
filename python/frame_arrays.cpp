#include "python/frame_arrays.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "app/output_check.h"
#include "io/core/image_writer.h"
#include "view/frame_image.h"

namespace tg::python {
namespace {

template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast> channel(const py::dict& d, const char* key,
                                                                  std::size_t count) {
  if (!d.contains(key)) throw std::invalid_argument(std::string("image: no \"") + key + "\" channel");
  auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(d[key]);
  if (!a || std::size_t(a.size()) != count)
    throw std::invalid_argument(std::string("image: the \"") + key + "\" channel has the wrong size");
  return a;
}

}  // namespace

py::array_t<float> floatImage(const std::vector<float>& v, int h, int w, int c) {
  std::vector<py::ssize_t> shape{h, w};
  if (c > 1) shape.push_back(c);
  py::array_t<float> a(shape);
  std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(float));
  return a;
}

void saveFrame(const py::dict& frame, const std::string& path, const InputList& inputs) {
  std::vector<app::NamedPath> read;
  for (const auto& [name, file] : inputs) read.push_back({name, file});
  app::refuseOutputsOverInputs({{"path", path}}, read);
  // A cast would write a float image in 0..1 as black: refused instead.
  const py::array given = py::array::ensure(frame["rgba"]);
  if (!given || !given.dtype().is(py::dtype::of<std::uint8_t>()))
    throw py::type_error("image: must be the (H, W, 4) uint8 image, not " +
                         (given ? std::string(py::str(given.dtype())) : std::string("a non-array")));
  auto rgba = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(frame["rgba"]);
  if (!rgba || rgba.ndim() != 3 || rgba.shape(2) != 4) throw std::invalid_argument("image: must be (H, W, 4) uint8");
  render::FrameImage img;
  img.height = int(rgba.shape(0));
  img.width = int(rgba.shape(1));
  const std::size_t n = std::size_t(img.width) * std::size_t(img.height);
  if (!io::canWriteImage(path)) throw std::invalid_argument("path: no image format for \"" + path + "\"");
  if (io::writesGeometryChannels(path)) {
    if (!frame.contains("depth"))
      throw std::invalid_argument("path: " + path + " stores depth, normal and id: render(..., channels=True)");
    auto color = channel<float>(frame, "color", 4 * n);
    auto depth = channel<float>(frame, "depth", n);
    auto normal = channel<float>(frame, "normal", 3 * n);
    auto id = channel<std::uint32_t>(frame, "id", n);
    img.rgba.assign(color.data(), color.data() + 4 * n);
    img.depth.assign(depth.data(), depth.data() + n);
    img.normalWC.assign(normal.data(), normal.data() + 3 * n);
    img.id.assign(id.data(), id.data() + n);
  } else {
    img.rgba.resize(4 * n);
    for (std::size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = float(rgba.data()[i]) / 255.0f;
  }
  py::gil_scoped_release release;
  io::writeImage(img, path);
}

}  // namespace tg::python
