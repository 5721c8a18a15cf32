#include "render/context_item.h"

namespace tg::render {

void drawContextOpaque(const gl::Api& gl, std::span<const std::unique_ptr<ContextItem>> items, const Camera& cam,
                       const FrameParams& p, ContextTarget target) {
  if (items.empty()) return;
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_GREATER);  // reversed Z
  gl.DepthMask(GL_TRUE);
  for (std::size_t i = 0; i < items.size(); ++i)
    if (items[i]->visible()) items[i]->drawOpaque(cam, p, kContextIdBase + std::uint32_t(i), target);
}

}  // namespace tg::render
