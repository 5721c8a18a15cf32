#pragma once
// Soft shadows from the key light (Sigg et al. 2006, §5): a light-space depth
// map of the same exact glyphs, filtered by percentage closer filtering
// (Reeves et al. 1987) in the deferred lighting pass.
//
//   Occluders   (superquadric frames, as the view's pre-pass) WRITES its own
//                      DEPTH32F occluder depth and R32F pyramid at map size,
//                      from the exact ellipsoids that superquadrics hold
//   Map pass    READS  the glyph records (the glyph programs, drawn from the
//                      light's orthographic camera), the occluders above
//               WRITES its own DEPTH32F map (reversed, window depth along the
//                      key light), mapSize x mapSize
//   Lighting    READS  G-buffer depth (unit TG_UNIT_SHADOW_SCENE_DEPTH), the map (unit
//                      TG_UNIT_SHADOW_MAP), and the G-buffer normals the pass already reads
//               WRITES nothing new: the key light's diffuse and specular terms
//                      are scaled by the filtered visibility (shaders/lib/shadow.glsl)
//
// Built on the first frame that asks for shadows and released by the first
// frame that does not, so that a frame without them allocates nothing (the
// renderer likewise keeps its TG_SHADOWS lighting variant only while used).
#include <cstddef>

#include <glm/vec3.hpp>

#include "gl/program.h"
#include "render/frame_pass.h"
#include "view/camera.h"
#include "render/gbuffer.h"
#include "render/occluder_pyramid.h"

namespace tg::render {

// The key light's orthographic camera for a view: looking along -keyDirWC;
// its window covers the part of the caster box `lo..hi` (WC) that the view
// can see, projected along the light (glyphs outside it cannot shadow a
// visible point), and its depth range covers the whole box towards the
// light, where casters of visible points lie. Square, with p.mapSize texels
// a side or fewer as p.mapDensity says.
Camera lightCamera(const Camera& view, const glm::dvec3& keyDirWC, const glm::dvec3& lo, const glm::dvec3& hi,
                   const ShadowParams& p);

class ShadowPass final : public FramePass {
 public:
  explicit ShadowPass(const gl::Api& gl);
  ~ShadowPass() override;
  ShadowPass(const ShadowPass&) = delete;
  ShadowPass& operator=(const ShadowPass&) = delete;

  // (Re)allocates the map for `mapSize`, clears it and binds its framebuffer
  // for the glyph programs to draw depth into.
  void beginMap(int mapSize);
  // The occlusion pre-pass from the light (GlyphRenderer::render's, at map
  // size): beginOccluders clears and binds a depth target for the exact
  // ellipsoids, buildPyramid reduces it and leaves both bound where
  // shaders/lib/occlusion.glsl reads them. Allocated on first use.
  void beginOccluders(int mapSize);
  void buildPyramid(const OccluderPyramid& pyramid) const;
  // Binds the map and target's depth, and sets the shadow uniforms of
  // `lighting`, lighting.frag compiled with TG_SHADOWS (the caller sets its
  // camera and light mix).
  void bindForLighting(const gl::Program& lighting, const Camera& view, const Camera& light, const ShadowParams& p,
                       const GBuffer& target) const;
  std::span<const Attachment> reads() const override { return {}; }
  std::span<const Attachment> writes() const override { return {}; }  // its own map
  // The key light's map of the glyphs (GlyphPath::drawShadowCasters) and the
  // visible context, which both cast and receive, from lightCamera over their box.
  void run(const PassFrame& f) override;
  std::size_t gpuBytes() const override;
  int mapSize() const { return size_; }  // of the last map drawn
  const Camera& light() const { return light_; }  // of the last map drawn

 private:
  void release();
  void releaseOccluders();
  const gl::Api& gl_;
  GLuint map_ = 0, fbo_ = 0;
  int size_ = 0;
  GLuint occluderDepth_ = 0, pyramid_ = 0, occluderFbo_ = 0;
  int occluderSize_ = 0;
  Camera light_{};
};

}  // namespace tg::render
