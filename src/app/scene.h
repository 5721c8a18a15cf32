#pragma once
// What a render or info command works on: a loaded (or built-in) field.
#include <optional>
#include <string>

#include "io/tensor_field.h"
#include "render/camera.h"

namespace tg::app {

struct Scene {
  io::TensorField field;
  std::optional<render::CameraDesc> preferredCamera;  // used when no camera flag is given
  std::optional<double> preferredFaMin;
};

// The built-in default scene: the helix phantom, seen obliquely, with the
// isotropic background hidden by an FA threshold.
Scene defaultScene();

}  // namespace tg::app
