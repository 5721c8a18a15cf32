#pragma once
// The viewer's camera: a turntable about the world up axis, as ParaView's and
// Slicer's default interaction, GL-free so that scripts and tests share it.
#include "view/anatomy.h"
#include "view/camera.h"

namespace tg::app {

class OrbitCamera {
 public:
  explicit OrbitCamera(const render::CameraDesc& initial) : initial_(initial), d_(initial) {}

  // Degrees: yaw turns about the up axis, pitch tilts towards it (stopping
  // 1 degree short of the pole, where the view would lose its up vector).
  void orbit(double yawDeg, double pitchDeg);
  // Moves the scene across the image by (dx, dy) view heights, right and up.
  void pan(double dx, double dy);
  // Brings the eye `factor` times closer (ortho: shrinks the view height).
  void zoom(double factor);
  void reset() { d_ = initial_; }
  // Looks from `axes` (view/anatomy.h), the look-at point and distance kept.
  void turn(const render::ViewAxes& axes) { d_ = render::turnedTo(d_, axes); }

  const render::CameraDesc& desc() const { return d_; }

 private:
  render::CameraDesc initial_, d_;
};

}  // namespace tg::app
