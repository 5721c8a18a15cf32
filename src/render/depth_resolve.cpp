#include "render/depth_resolve.h"

#include <stdexcept>
#include <string>

#include "shaders/lib/bindings.h"

namespace tg::render {

DepthResolve::DepthResolve(const gl::Api& gl, const gl::ShaderLibrary& lib, int width, int height)
    : gl_(gl),
      program_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "depth_resolve.frag"}}),
      width_(width),
      height_(height) {
  gl.CreateTextures(GL_TEXTURE_2D, 1, &tex_);
  gl.TextureStorage2D(tex_, 1, GL_R32F, width, height);
  gl.TextureParameteri(tex_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TextureParameteri(tex_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.CreateVertexArrays(1, &vao_);
  gl::checkError(gl, "DepthResolve");
}

DepthResolve::~DepthResolve() {
  gl_.DeleteTextures(1, &tex_);
  gl_.DeleteVertexArrays(1, &vao_);
}

void DepthResolve::upload(std::span<const float> windowDepth) const {
  if (windowDepth.size() != std::size_t(width_) * std::size_t(height_))
    throw std::invalid_argument("DepthResolve::upload: " + std::to_string(windowDepth.size()) + " depths for " +
                                std::to_string(width_) + "x" + std::to_string(height_));
  gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl_.TextureSubImage2D(tex_, 0, 0, 0, width_, height_, GL_RED, GL_FLOAT, windowDepth.data());
}

void DepthResolve::resolve(const GBuffer& target) const {
  if (target.width() != width_ || target.height() != height_)
    throw std::invalid_argument("DepthResolve::resolve: target is not the channel's size");
  // A compute shader's stores must land before the fetch.
  gl_.MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_ALWAYS);
  gl_.DepthMask(GL_TRUE);
  gl_.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl_.BindTextureUnit(TG_UNIT_RESOLVE_DEPTH, tex_);
  gl_.UseProgram(program_.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl_.DepthFunc(GL_GREATER);  // reversed Z, as the raster path leaves it
  gl::checkError(gl_, "DepthResolve::resolve");
}

}  // namespace tg::render
