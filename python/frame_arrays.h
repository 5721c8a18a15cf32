#pragma once
// What the module gives back and saves: channels as NumPy arrays, and a
// rendered frame written through the CLI's image writers (python/module.cpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <utility>
#include <vector>

namespace tg::python {

namespace py = pybind11;

// (keyword, path) of each file a frame was drawn from.
using InputList = std::vector<std::pair<std::string, std::string>>;

// `v` as an (h, w) or (h, w, c) float array.
py::array_t<float> floatImage(const std::vector<float>& v, int h, int w, int c);

// Writes what render() returned through the CLI's writers: .exr takes the
// float and geometry channels (render(..., channels=True)), every other
// format the 8-bit image. First the CLI's output checks: no directory, FIFO,
// socket or device, no missing directory, none of the files the frame was
// drawn from (`inputs`).
void saveFrame(const py::dict& frame, const std::string& path, const InputList& inputs);

}  // namespace tg::python
