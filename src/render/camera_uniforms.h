#pragma once
// The camera uniforms of shaders/lib/camera.glsl, for every program that
// includes it: the glyph passes and the deferred ones.
#include "gl/program.h"
#include "view/camera.h"

namespace tg::render {

void setCameraUniforms(const gl::Program& prog, const Camera& cam);

}  // namespace tg::render
