// The plugin's side of sharing a GL context with its host (ParaView's VTK):
// entry points from the host's current context, the state our passes change
// saved and put back, and the copy of the lit glyphs into the host's
// framebuffer with depth in the host's convention.
#pragma once
#include <array>

#include "gl/loader.h"
#include "gl/program.h"
#include "view/camera.h"
#include "render/gbuffer.h"

namespace tg::paraview {

// The entry points of the context current on this thread, through the
// GetProcAddress of whichever API made it: GLX (ParaView under X), EGL or
// OSMesa (headless ParaView builds). Nothing is linked: each API is looked up
// among the libraries the host already loaded. Throws std::runtime_error when
// no context is current.
struct HostGL {
  gl::Api api;
  // Beyond the renderer's table: for reading each texture unit's binding.
  PFNGLACTIVETEXTUREPROC ActiveTexture = nullptr;
  PFNGLCOLORMASKPROC ColorMask = nullptr;
  const char* apiName = "";
};
HostGL loadHostGL();

// What the renderer's passes change and the host relies on: framebuffer
// bindings, viewport, depth, blend and clip state, program, vertex array,
// texture units 0-15 and the first image units. Saved on construction, put
// back on destruction, so the host's own state cache (vtkOpenGLState) stays
// true. In between, neutral() sets what the renderer takes for granted (GL's
// defaults): VTK leaves blending, scissoring and the like on.
class HostState {
 public:
  explicit HostState(const HostGL& host);
  ~HostState();
  HostState(const HostState&) = delete;
  HostState& operator=(const HostState&) = delete;
  GLint drawFramebuffer() const { return drawFbo_; }
  void neutral() const;

 private:
  const HostGL& host_;
  GLint drawFbo_ = 0, readFbo_ = 0, program_ = 0, vao_ = 0, activeTexture_ = 0, clipOrigin_ = 0, clipDepth_ = 0;
  GLint viewport_[4] = {}, depthFunc_ = 0, blendSrcRgb_ = 0, blendDstRgb_ = 0, blendSrcA_ = 0, blendDstA_ = 0;
  GLint indirect_ = 0, packAlignment_ = 0, unpackAlignment_ = 0;
  GLboolean depthTest_ = 0, depthMask_ = 0, blend_ = 0, cull_ = 0, scissor_ = 0, stencil_ = 0, offset_ = 0,
            srgb_ = 0;
  GLint colorMask_[4] = {1, 1, 1, 1};
  std::array<GLint, 16> textures_{};
};

// What the composite writes as colour (shaders/host_composite.frag): the lit
// glyphs, or what one of the host's selection passes reads back: a constant
// colour (prop, composite or process id), or each glyph's input point id
// split into its low 24 bits (RGB bytes) and its bits 24..31 (red), or its
// block's flat index (composite inputs). `blocks` (a buffer of `blockCount`
// (first id, flat index) pairs; none: one dataset) maps glyph ids to blocks.
struct CompositeOutput {
  enum class Kind { Lit = 0, Constant = 1, IdLow24 = 2, IdHigh8 = 3, CompositeIndex = 4 };
  Kind kind = Kind::Lit;
  glm::vec3 constant{0.0f};
  GLuint blocks = 0;
  int blockCount = 0;
  // Lit only: below 1, blended over the framebuffer (source alpha), the
  // framebuffer's alpha kept.
  float opacity = 1.0f;
};

// Draws the glyphs of `target` into the bound host framebuffer: colour as
// `out` says, and gl_FragDepth re-projected through the host's view -> clip matrix
// (`hostProjVCCC`, row-major, GL's [-1, 1] clip depth and glDepthRange 0..1),
// depth-tested against what the host drew before. Pixels without a glyph are
// left alone.
class HostComposite {
 public:
  HostComposite(const gl::Api& gl, const gl::ShaderLibrary& lib);
  ~HostComposite();
  HostComposite(const HostComposite&) = delete;
  HostComposite& operator=(const HostComposite&) = delete;
  void draw(const render::Camera& cam, const render::GBuffer& target, const double hostProjVCCC[16], int originX,
            int originY, const CompositeOutput& out = {}) const;

 private:
  const gl::Api& gl_;
  gl::Program program_;
  GLuint vao_ = 0;
};

}  // namespace tg::paraview
