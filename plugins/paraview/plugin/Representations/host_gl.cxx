#include "host_gl.h"

#include <dlfcn.h>

#include <stdexcept>

#include "render/camera_uniforms.h"

namespace tg::paraview {
namespace {

using CurrentContextFn = void* (*)();
using GetProcFn = void* (*)(const char*);

template <class F>
F lookup(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, name));
}

}  // namespace

HostGL loadHostGL() {
  // Which API's context is current: the host made it, and its library is
  // already loaded (ParaView 5.11 on Debian: GLX through libGLX).
  struct Candidate {
    const char *name, *current, *getProc;
  };
  const Candidate candidates[] = {{"glx", "glXGetCurrentContext", "glXGetProcAddressARB"},
                                  {"egl", "eglGetCurrentContext", "eglGetProcAddress"},
                                  {"osmesa", "OSMesaGetCurrentContext", "OSMesaGetProcAddress"}};
  for (const Candidate& c : candidates) {
    const auto current = lookup<CurrentContextFn>(c.current);
    const auto getProc = lookup<GetProcFn>(c.getProc);
    if (!current || !getProc || !current()) continue;
    HostGL host;
    host.api = gl::loadApi([getProc](const char* fn) { return getProc(fn); });
    host.ActiveTexture = reinterpret_cast<PFNGLACTIVETEXTUREPROC>(getProc("glActiveTexture"));
    host.ColorMask = reinterpret_cast<PFNGLCOLORMASKPROC>(getProc("glColorMask"));
    if (!host.ActiveTexture || !host.ColorMask)
      throw std::runtime_error("loadHostGL: the host's context lacks glActiveTexture or glColorMask");
    host.apiName = c.name;
    return host;
  }
  throw std::runtime_error("loadHostGL: no GLX, EGL or OSMesa context is current in this process");
}

HostState::HostState(const HostGL& host) : host_(host) {
  const gl::Api& gl = host.api;
  gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo_);
  gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFbo_);
  gl.GetIntegerv(GL_CURRENT_PROGRAM, &program_);
  gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
  gl.GetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
  gl.GetIntegerv(GL_CLIP_ORIGIN, &clipOrigin_);
  gl.GetIntegerv(GL_CLIP_DEPTH_MODE, &clipDepth_);
  gl.GetIntegerv(GL_VIEWPORT, viewport_);
  gl.GetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
  gl.GetIntegerv(GL_BLEND_SRC_RGB, &blendSrcRgb_);
  gl.GetIntegerv(GL_BLEND_DST_RGB, &blendDstRgb_);
  gl.GetIntegerv(GL_BLEND_SRC_ALPHA, &blendSrcA_);
  gl.GetIntegerv(GL_BLEND_DST_ALPHA, &blendDstA_);
  gl.GetIntegerv(GL_DRAW_INDIRECT_BUFFER_BINDING, &indirect_);
  gl.GetIntegerv(GL_PACK_ALIGNMENT, &packAlignment_);
  gl.GetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment_);  // the cpu path's uploads change it
  GLint b = 0;
  auto flag = [&](GLenum e, GLboolean& out) {
    gl.GetIntegerv(e, &b);
    out = b ? GL_TRUE : GL_FALSE;
  };
  flag(GL_DEPTH_TEST, depthTest_);
  flag(GL_DEPTH_WRITEMASK, depthMask_);
  flag(GL_BLEND, blend_);
  flag(GL_CULL_FACE, cull_);
  flag(GL_SCISSOR_TEST, scissor_);
  flag(GL_STENCIL_TEST, stencil_);
  flag(GL_POLYGON_OFFSET_FILL, offset_);
  flag(GL_FRAMEBUFFER_SRGB, srgb_);
  gl.GetIntegerv(GL_COLOR_WRITEMASK, colorMask_);
  for (GLuint u = 0; u < textures_.size(); ++u) {
    host.ActiveTexture(GL_TEXTURE0 + u);
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &textures_[u]);
  }
  host.ActiveTexture(GLenum(activeTexture_));
}

HostState::~HostState() {
  const gl::Api& gl = host_.api;
  gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFbo_));
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFbo_));
  gl.UseProgram(GLuint(program_));
  gl.BindVertexArray(GLuint(vao_));
  gl.ClipControl(GLenum(clipOrigin_), GLenum(clipDepth_));
  gl.Viewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  gl.DepthFunc(GLenum(depthFunc_));
  gl.DepthMask(depthMask_);
  gl.BlendFuncSeparate(GLenum(blendSrcRgb_), GLenum(blendDstRgb_), GLenum(blendSrcA_), GLenum(blendDstA_));
  gl.BindBuffer(GL_DRAW_INDIRECT_BUFFER, GLuint(indirect_));
  gl.PixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment_);
  auto set = [&](GLenum e, GLboolean on) { on ? gl.Enable(e) : gl.Disable(e); };
  set(GL_DEPTH_TEST, depthTest_);
  set(GL_BLEND, blend_);
  set(GL_CULL_FACE, cull_);
  set(GL_SCISSOR_TEST, scissor_);
  set(GL_STENCIL_TEST, stencil_);
  set(GL_POLYGON_OFFSET_FILL, offset_);
  set(GL_FRAMEBUFFER_SRGB, srgb_);
  host_.ColorMask(GLboolean(colorMask_[0]), GLboolean(colorMask_[1]), GLboolean(colorMask_[2]),
                  GLboolean(colorMask_[3]));
  // Units the host left empty are unbound too: BindTextureUnit(u, 0) clears every target.
  for (GLuint u = 0; u < textures_.size(); ++u) gl.BindTextureUnit(u, GLuint(textures_[u]));
  host_.ActiveTexture(GLenum(activeTexture_));
  gl.BindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
  gl.BindImageTexture(1, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
}

void HostState::neutral() const {
  const gl::Api& gl = host_.api;
  for (GLenum e : {GL_BLEND, GL_CULL_FACE, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_POLYGON_OFFSET_FILL, GL_FRAMEBUFFER_SRGB})
    gl.Disable(e);
  host_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

HostComposite::HostComposite(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl), program_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "host_composite.frag"}}) {
  gl.CreateVertexArrays(1, &vao_);
}

HostComposite::~HostComposite() { gl_.DeleteVertexArrays(1, &vao_); }

void HostComposite::draw(const render::Camera& cam, const render::GBuffer& target, const double hostProjVCCC[16],
                         int originX, int originY, const CompositeOutput& out) const {
  render::setCameraUniforms(program_, cam);
  program_.set("uOutput", int(out.kind));
  program_.set("uSelectColor", out.constant);
  program_.set("uBlockCount", out.blocks ? out.blockCount : 0);
  if (out.blocks) gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, out.blocks);
  program_.set("uOriginDC", glm::vec2(float(originX), float(originY)));
  program_.set("uHostZRow", glm::vec4(float(hostProjVCCC[8]), float(hostProjVCCC[9]), float(hostProjVCCC[10]),
                                      float(hostProjVCCC[11])));
  program_.set("uHostWRow", glm::vec4(float(hostProjVCCC[12]), float(hostProjVCCC[13]), float(hostProjVCCC[14]),
                                      float(hostProjVCCC[15])));
  gl_.Viewport(originX, originY, cam.width, cam.height);
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LEQUAL);
  gl_.DepthMask(GL_TRUE);
  const bool blend = out.kind == CompositeOutput::Kind::Lit && out.opacity < 1.0f;
  program_.set("uOpacity", blend ? out.opacity : 1.0f);
  if (blend) {
    gl_.Enable(GL_BLEND);
    gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  } else {
    gl_.Disable(GL_BLEND);
  }
  gl_.BindTextureUnit(0, target.color());
  gl_.BindTextureUnit(1, target.depth());
  gl_.BindTextureUnit(2, target.id());
  gl_.UseProgram(program_.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl::checkError(gl_, "HostComposite::draw");
}

}  // namespace tg::paraview
