#include "render/tract_item.h"

#include <bit>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include "render/camera_uniforms.h"
#include "render/frame_params.h"
#include "shaders/lib/bindings.h"

namespace tg::render {

std::size_t drawableStreamlines(std::span<const std::uint64_t> starts) {
  std::size_t n = 0;
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) n += starts[k + 1] >= starts[k] + 2 ? 1 : 0;
  return n;
}

TractItem::TractItem(const gl::Api& gl, const gl::ShaderLibrary& lib, std::string label,
                     std::span<const float> positionsWC, std::span<const std::uint64_t> starts,
                     const TractParams& params)
    : gl_(gl), lib_(lib), label_(std::move(label)), params_(params) {
  const std::size_t points = positionsWC.size() / 3;
  if (positionsWC.size() % 3 || starts.empty() || starts[0] != 0 || starts.back() != points)
    throw std::invalid_argument("TractItem: " + label_ + ": streamlines do not cover the points");
  for (std::size_t k = 1; k < starts.size(); ++k)
    if (starts[k] < starts[k - 1]) throw std::invalid_argument("TractItem: " + label_ + ": streamlines out of order");
  streamlines_ = drawableStreamlines(starts);
  if (streamlines_ == 0) throw std::invalid_argument("TractItem: " + label_ + ": no streamline of two or more points");
  // A separator before each drawn streamline and after the last, so that
  // every point's neighbours exist and segments never join two streamlines.
  std::vector<glm::vec4> slots;
  slots.reserve(points + streamlines_ + 1);
  slots.emplace_back(0.0f);
  loWC_ = glm::dvec3(INFINITY);
  hiWC_ = glm::dvec3(-INFINITY);
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
    if (starts[k + 1] < starts[k] + 2) continue;
    for (std::uint64_t i = starts[k]; i < starts[k + 1]; ++i) {
      const glm::vec3 p(positionsWC[3 * i], positionsWC[3 * i + 1], positionsWC[3 * i + 2]);
      slots.emplace_back(p, 1.0f);
      loWC_ = glm::min(loWC_, glm::dvec3(p));
      hiWC_ = glm::max(hiWC_, glm::dvec3(p));
    }
    segments_ += starts[k + 1] - starts[k] - 1;
    slots.emplace_back(0.0f);
  }
  slots_ = slots.size();
  if (6 * (slots_ - 1) > std::size_t(INT32_MAX))
    throw std::invalid_argument("TractItem: " + label_ + ": more segments than one draw takes");
  gl.CreateVertexArrays(1, &vao_);
  gl.CreateBuffers(1, &points_);
  gl.NamedBufferStorage(points_, GLsizeiptr(slots.size() * sizeof(glm::vec4)), slots.data(), 0);
  gl::checkError(gl, "TractItem");
}

TractItem::~TractItem() {
  gl_.DeleteBuffers(1, &points_);
  gl_.DeleteVertexArrays(1, &vao_);
}

void TractItem::drawOpaque(const Camera& cam, const FrameParams& /*p*/, std::uint32_t id, ContextTarget /*target*/) {
  if (!program_)
    program_ = std::make_unique<gl::Program>(
        gl_, lib_, std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, "tract.vert"}, {GL_FRAGMENT_SHADER, "tract.frag"}});
  setCameraUniforms(*program_, cam);
  program_->set("uColor", params_.color);
  program_->set("uByDirection", params_.byDirection ? 1 : 0);
  program_->set("uRadiusWC", 0.5f * params_.widthWC);
  program_->set("uId", std::bit_cast<int>(id));
  gl_.UseProgram(program_->id());
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_TRACT_POINTS, points_);
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, GLsizei(6 * (slots_ - 1)));
  gl::checkError(gl_, "TractItem::drawOpaque");
}

}  // namespace tg::render
