#include "render/occluder_pyramid.h"

#include <algorithm>

namespace tg::render {

OccluderPyramid::OccluderPyramid(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl), build_(gl, lib, {{GL_COMPUTE_SHADER, "occluder_pyramid.comp"}}) {}

void OccluderPyramid::build(const GBuffer& target) const {
  gl_.BindTextureUnit(kDepthUnit, target.occluderDepth());
  gl_.UseProgram(build_.id());
  const GLuint pyramid = target.occluderPyramid();
  for (int level = 0; level < target.pyramidLevels(); ++level) {
    build_.set("uFromDepth", level == 0 ? 1 : 0);
    if (level > 0) gl_.BindImageTexture(0, pyramid, level - 1, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    gl_.BindImageTexture(1, pyramid, level, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    const int w = std::max(1, target.pyramidWidth() >> level), h = std::max(1, target.pyramidHeight() >> level);
    gl_.DispatchCompute(GLuint((w + 7) / 8), GLuint((h + 7) / 8), 1);
    gl_.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  }
  // Unbound, so that no image unit still holds a level while the sprites sample it.
  gl_.BindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
  gl_.BindImageTexture(1, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  gl_.BindTextureUnit(kPyramidUnit, pyramid);
  gl::checkError(gl_, "OccluderPyramid::build");
}

}  // namespace tg::render
