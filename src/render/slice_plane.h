#pragma once
// Slice planes (`--underlay`, `--plane`): a scalar volume sampled on a plane
// in world coordinates, drawn into the glyphs' G-buffer and shadow map as a
// context item (render/context_item.h).
//
//   Geometry    READS  the volume (one R32F 3D texture, shared by the planes
//                      of one underlay; linear or nearest per SliceParams)
//               WRITES albedo (the colormap over the window), normalWC (the
//                      plane's normal, turned to face the camera), id, and
//                      depth: that of the plane moved SliceParams::
//                      depthOffsetRadii largest glyph radii away from the
//                      camera, so glyphs centred on it are not cut
//   Shadow map  WRITES depth, offset alike from the light
//
// Nothing of it exists until a plane is made: no program, no texture.
#include <memory>

#include "gl/program.h"
#include "render/context_item.h"
#include "view/underlay.h"

namespace tg::render {

// The volume on the GPU, and the program that draws its planes.
class SliceVolume {
 public:
  // Throws std::invalid_argument when the grid exceeds GL_MAX_3D_TEXTURE_SIZE.
  SliceVolume(const gl::Api& gl, const gl::ShaderLibrary& lib, UnderlayVolume volume);
  ~SliceVolume();
  SliceVolume(const SliceVolume&) = delete;
  SliceVolume& operator=(const SliceVolume&) = delete;

  const UnderlayVolume& volume() const { return volume_; }
  // p.window, or p's percentiles of the finite values (computed once per pair).
  std::pair<double, double> window(const SliceParams& p) const;
  void draw(const Camera& cam, const PlaneQuad& q, const SliceParams& p, double offsetWC, std::uint32_t id) const;
  std::size_t gpuBytes() const { return volume_.voxels() * sizeof(float); }

 private:
  const gl::Api& gl_;
  gl::Program program_;
  UnderlayVolume volume_;
  GLuint texture_ = 0, vao_ = 0;
  mutable std::pair<double, double> percentiles_{-1, -1}, window_{0, 1};
};

class SlicePlane : public ContextItem {
 public:
  // `maxAbsEigenvalue`: the glyphs' largest |eigenvalue|, whose glyph radius
  // at each frame's scale and sizing sets the depth offset. Throws
  // std::invalid_argument for a plane outside the volume (planeQuad).
  SlicePlane(std::shared_ptr<const SliceVolume> volume, const PlaneSpec& spec, const SliceParams& params,
             double maxAbsEigenvalue);

  const PlaneSpec& spec() const { return spec_; }
  void setSpec(const PlaneSpec& spec);  // throws as the constructor; the plane is unchanged then
  const SliceParams& params() const { return params_; }
  void setParams(const SliceParams& params) { params_ = params; }
  const SliceVolume& volume() const { return *volume_; }
  // World units the plane is drawn behind itself at `p`'s glyph size.
  double depthOffsetWC(const FrameParams& p) const;

  std::string label() const override { return spec_.label(); }
  void drawOpaque(const Camera& cam, const FrameParams& p, std::uint32_t id, ContextTarget target) override;
  std::pair<glm::dvec3, glm::dvec3> boundsWC() const override;
  std::optional<double> valueAt(const glm::dvec3& pointWC) const override;
  std::optional<glm::dvec3> trueSurface(const glm::dvec3& originWC, const glm::dvec3& dirWC) const override;
  // The underlay's name, colormap and the window the plane is drawn with.
  std::optional<UnderlayKey> legendKey() const override;
  // Its share of the volume's texture: the planes of one underlay add up to it.
  std::size_t gpuBytes() const override;

 private:
  std::shared_ptr<const SliceVolume> volume_;
  PlaneSpec spec_;
  PlaneQuad quad_;
  SliceParams params_;
  double maxAbsEigenvalue_;
};

}  // namespace tg::render
