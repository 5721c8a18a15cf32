#pragma once
// Streamlines in the scene's context (render/context_item.h): --tracts.
// Drawn as tubes of a radius in world units (at least half a pixel wide):
// each segment is a camera-facing quad along its streamline, shaded with the
// normal a tube would have across it and written at the tube's front
// surface depth, the "pseudotubes" mrview draws. So they are lit, shadowed,
// occluded by and occlude the glyphs, take the depth cues and are picked as
// any context item.
//
//   WRITES the G-buffer (albedo: the local direction |x| |y| |z| or a fixed
//          colour, normalWC, id, reversed-Z depth) and the key light's shadow map.
//
// Keeps no CPU copy: one vec4 per point (w 0 between streamlines) on the GPU.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include <glm/vec3.hpp>

#include "gl/program.h"
#include "render/context_item.h"

namespace tg::render {

// One home for the tracts' drawing options: the CLI, the viewer and Python read these defaults.
struct TractParams {
  bool byDirection = true;                // colour by local direction; else `color`
  glm::vec3 color{0.95f, 0.85f, 0.55f};   // with byDirection false
  float widthWC = 0.5f;                   // tube diameter, world units (mm in DTI)
  bool operator==(const TractParams&) const = default;
};

class TractItem : public ContextItem {
 public:
  // `positionsWC`: 3 floats per point; streamline k is points starts[k] ..
  // starts[k + 1] - 1 (checked: std::invalid_argument). Streamlines of fewer
  // than two points have no segment and are not drawn.
  TractItem(const gl::Api& gl, const gl::ShaderLibrary& lib, std::string label, std::span<const float> positionsWC,
            std::span<const std::uint64_t> starts, const TractParams& params = {});
  ~TractItem() override;
  TractItem(const TractItem&) = delete;
  TractItem& operator=(const TractItem&) = delete;

  std::string label() const override { return label_; }
  void drawOpaque(const Camera& cam, const FrameParams& p, std::uint32_t id, ContextTarget target) override;
  std::pair<glm::dvec3, glm::dvec3> boundsWC() const override { return {loWC_, hiWC_}; }
  std::size_t gpuBytes() const override { return 16 * slots_; }

  const TractParams& params() const { return params_; }
  void setParams(const TractParams& p) { params_ = p; }
  std::size_t segmentCount() const { return segments_; }
  std::size_t streamlineCount() const { return streamlines_; }

 private:
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  std::string label_;
  TractParams params_;
  std::size_t slots_ = 0, segments_ = 0, streamlines_ = 0;
  glm::dvec3 loWC_{0.0}, hiWC_{0.0};
  GLuint vao_ = 0, points_ = 0;
  std::unique_ptr<gl::Program> program_;
};

// The streamlines of two or more points among `starts` (the ones drawn).
std::size_t drawableStreamlines(std::span<const std::uint64_t> starts);

}  // namespace tg::render
