#include "render/occluder_pyramid.h"

#include <algorithm>

#include "shaders/lib/bindings.h"

namespace tg::render {

OccluderPyramid::OccluderPyramid(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl),
      fromDepth_(gl, lib, {{GL_COMPUTE_SHADER, "occluder_pyramid.comp"}}, {"TG_FROM_DEPTH"}),
      fromFiner_(gl, lib, {{GL_COMPUTE_SHADER, "occluder_pyramid.comp"}}) {}

void OccluderPyramid::build(const GBuffer& target) const {
  build(target.occluderDepth(), target.occluderPyramid(), target.width(), target.height(), target.pyramidLevels());
}

int OccluderPyramid::levelsFor(int width, int height) {
  int levels = 1;  // down to 1 x 1, from half size
  while ((std::max((width + 1) / 2, (height + 1) / 2) >> levels) > 0) ++levels;
  return levels;
}

void OccluderPyramid::build(GLuint depth, GLuint pyramid, int width, int height, int levels) const {
  gl_.BindTextureUnit(TG_UNIT_OCCLUDER_DEPTH, depth);
  const int pyramidWidth = (width + 1) / 2, pyramidHeight = (height + 1) / 2;
  for (int level = 0; level < levels; ++level) {
    gl_.UseProgram(level == 0 ? fromDepth_.id() : fromFiner_.id());
    if (level > 0) gl_.BindImageTexture(TG_IMAGE_PYRAMID_FINER, pyramid, level - 1, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    gl_.BindImageTexture(TG_IMAGE_PYRAMID_COARSER, pyramid, level, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    const int w = std::max(1, pyramidWidth >> level), h = std::max(1, pyramidHeight >> level);
    gl_.DispatchCompute(GLuint((w + 7) / 8), GLuint((h + 7) / 8), 1);
    gl_.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  }
  // Unbound, so that no image unit still holds a level while the sprites sample it.
  gl_.BindImageTexture(TG_IMAGE_PYRAMID_FINER, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
  gl_.BindImageTexture(TG_IMAGE_PYRAMID_COARSER, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  gl_.BindTextureUnit(TG_UNIT_OCCLUDER_PYRAMID, pyramid);
  gl::checkError(gl_, "OccluderPyramid::build");
}

}  // namespace tg::render
