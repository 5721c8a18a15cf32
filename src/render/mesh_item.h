#pragma once
// A triangle mesh in the scene's context (render/context_item.h): a part's
// surface from --mesh, or the boundary of the tensors' FEM mesh.
//
//   Opaque      WRITES the G-buffer (albedo, flat normalWC, id, reversed-Z
//                      depth) and casts into the key light's shadow map
//   SeeThrough  after lighting: a single depth-peeled front layer. Pass 1
//                      WRITES its own DEPTH32F texture with the mesh's nearest
//                      surface (depth only); pass 2 READS the G-buffer depth and
//                      draws the mesh again with an EQUAL test against pass 1,
//                      lit here and blended over the lit colour where it lies
//                      in front of the opaque scene. Glyphs inside stay visible
//                      and pickable (no id written); it casts no shadow.
//   Edges       WRITES the G-buffer as lines: the feature edges, i.e. boundary
//                      and non-manifold edges and those whose two faces meet
//                      at more than featureAngleDeg (not every triangle edge,
//                      so a hex mesh's boundary shows its faces, not their
//                      triangulation). Computed on first use, from the
//                      GPU's copy: the item keeps no CPU copy of the mesh.
//
// Nothing is compiled or allocated beyond the mesh's buffers until a mode
// needs it.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include <glm/vec3.hpp>

#include "gl/program.h"
#include "render/context_item.h"

namespace tg::render {

enum class MeshMode { Opaque, SeeThrough, Edges };

// One home for a mesh's drawing options: the CLI, the viewer and scripts read these defaults.
struct MeshParams {
  MeshMode mode = MeshMode::Opaque;
  glm::vec3 color{0.72f, 0.72f, 0.70f};
  float opacity = 0.25f;          // see-through: at a face seen head-on; more towards the outline
  float featureAngleDeg = 30.0f;  // edges: a crease sharper than this is drawn
  bool operator==(const MeshParams&) const = default;
};

const char* meshModeName(MeshMode m);

class MeshItem : public ContextItem {
 public:
  // `positionsWC`: 3 floats per vertex; `triangles`: 3 indices per triangle,
  // each below the vertex count (checked: std::invalid_argument).
  MeshItem(const gl::Api& gl, const gl::ShaderLibrary& lib, std::string label, std::span<const float> positionsWC,
           std::span<const std::uint32_t> triangles, const MeshParams& params = {});
  ~MeshItem() override;
  MeshItem(const MeshItem&) = delete;
  MeshItem& operator=(const MeshItem&) = delete;

  std::string label() const override { return label_; }
  void drawOpaque(const Camera& cam, const FrameParams& p, std::uint32_t id, ContextTarget target) override;
  bool translucent() const override { return params_.mode == MeshMode::SeeThrough; }
  void drawTranslucent(const Camera& cam, const FrameParams& p, const GBuffer& target) override;
  std::pair<glm::dvec3, glm::dvec3> boundsWC() const override { return {loWC_, hiWC_}; }
  std::size_t gpuBytes() const override;

  const MeshParams& params() const { return params_; }
  void setParams(const MeshParams& p);
  std::size_t triangleCount() const { return triangleCount_; }
  std::size_t edgeCount() const { return edgeCount_; }  // feature edges, once drawn as edges
  bool forwardProgramBuilt() const { return forward_ != nullptr; }

 private:
  void buildEdges();
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  std::string label_;
  MeshParams params_;
  std::size_t triangleCount_ = 0, vertexCount_ = 0, edgeCount_ = 0;
  float edgesAngleDeg_ = -1.0f;  // the angle the edge buffer was built for
  glm::dvec3 loWC_{0.0}, hiWC_{0.0};
  GLuint vao_ = 0, vertices_ = 0, triangles_ = 0, edges_ = 0;
  std::unique_ptr<gl::Program> gbuffer_, forward_;
  // See-through: the front layer's depth, and a framebuffer of it with the target's lit colour.
  GLuint peelDepth_ = 0, peelFbo_ = 0, blendFbo_ = 0;
  int peelWidth_ = 0, peelHeight_ = 0;
  GLuint peelColor_ = 0;  // the colour texture blendFbo_ holds
};

}  // namespace tg::render
