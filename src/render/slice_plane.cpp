#include "render/slice_plane.h"

#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "render/camera_uniforms.h"
#include "render/frame_params.h"
#include "tensor/glyph_scale.h"
#include "shaders/lib/bindings.h"

namespace tg::render {

SliceVolume::SliceVolume(const gl::Api& gl, const gl::ShaderLibrary& lib, UnderlayVolume volume)
    : gl_(gl),
      program_(gl, lib, {{GL_VERTEX_SHADER, "slice_plane.vert"}, {GL_FRAGMENT_SHADER, "slice_plane.frag"}}),
      volume_(std::move(volume)) {
  GLint maxSide = 0;
  gl.GetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSide);
  for (int a = 0; a < 3; ++a)
    if (volume_.dims[a] < 1 || volume_.dims[a] > maxSide)
      throw std::invalid_argument("SliceVolume: " + volume_.name + ": grid " + std::to_string(volume_.dims[0]) + "x" +
                                  std::to_string(volume_.dims[1]) + "x" + std::to_string(volume_.dims[2]) +
                                  " exceeds this GL's 3D textures (at most " + std::to_string(maxSide) + " a side)");
  if (volume_.values.size() != volume_.voxels())
    throw std::invalid_argument("SliceVolume: " + volume_.name + ": values do not fill the grid");
  gl.CreateTextures(GL_TEXTURE_3D, 1, &texture_);
  gl.TextureStorage3D(texture_, 1, GL_R32F, volume_.dims[0], volume_.dims[1], volume_.dims[2]);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TextureSubImage3D(texture_, 0, 0, 0, 0, volume_.dims[0], volume_.dims[1], volume_.dims[2], GL_RED, GL_FLOAT,
                       volume_.values.data());
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    gl.TextureParameteri(texture_, wrap, GL_CLAMP_TO_EDGE);
  gl.CreateVertexArrays(1, &vao_);
  gl::checkError(gl, "SliceVolume");
}

SliceVolume::~SliceVolume() {
  gl_.DeleteTextures(1, &texture_);
  gl_.DeleteVertexArrays(1, &vao_);
}

std::pair<double, double> SliceVolume::window(const SliceParams& p) const {
  if (p.window) return *p.window;
  if (percentiles_ != std::pair(p.percentileLo, p.percentileHi)) {
    window_ = percentileWindow(volume_.values, p.percentileLo, p.percentileHi);
    percentiles_ = {p.percentileLo, p.percentileHi};
  }
  return window_;
}

void SliceVolume::draw(const Camera& cam, const PlaneQuad& q, const SliceParams& p, double offsetWC,
                       std::uint32_t id) const {
  // The normal that faces this camera: towards the eye, or against the
  // orthographic view direction.
  const glm::dmat4 wcFromVC = glm::inverse(cam.viewWCVC);
  const glm::dvec3 towardsEye = cam.desc.projection == Projection::Orthographic
                                    ? -cam.viewDirectionWC()
                                    : glm::dvec3(wcFromVC[3]) - q.pointWC;
  const glm::dvec3 facing = glm::dot(q.normalWC, towardsEye) >= 0 ? q.normalWC : -q.normalWC;
  // The offset plane in VC, as (n, w) with n·x = w: in double, then rounded once.
  const glm::dvec3 nVC = glm::dmat3(cam.viewWCVC) * facing;
  const glm::dvec3 pVC = glm::dvec3(cam.viewWCVC * glm::dvec4(q.pointWC, 1.0));
  // Texture coordinates from WC: (index + 0.5) / dims.
  const glm::dmat4 indexFromWC = glm::inverse(volume_.indexToWC);
  glm::dmat4 texFromIndex(1.0);
  for (int a = 0; a < 3; ++a) {
    texFromIndex[a][a] = 1.0 / volume_.dims[a];
    texFromIndex[3][a] = 0.5 / volume_.dims[a];
  }
  glm::vec4 corners[4];
  for (int k = 0; k < 4; ++k) corners[k] = glm::vec4(glm::vec3(q.cornersWC[k]), 1.0f);
  const auto [lo, hi] = window(p);
  setCameraUniforms(program_, cam);
  program_.set("uCornersWC", std::span<const glm::vec4>(corners, 4));
  program_.set("uTexFromWC", glm::mat4(texFromIndex * indexFromWC));
  program_.set("uPlaneVC", glm::vec4(glm::vec3(nVC), float(glm::dot(nVC, pVC) - offsetWC)));
  program_.set("uNormalWC", glm::vec3(facing));
  program_.set("uWindow", glm::vec2(float(lo), float(hi)));
  program_.set("uColormap", int(p.colormap));
  program_.set("uIdBits", int(id));
  const GLint filter = p.linear ? GL_LINEAR : GL_NEAREST;
  gl_.TextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, filter);
  gl_.TextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, filter);
  gl_.BindTextureUnit(TG_UNIT_SLICE, texture_);
  gl_.UseProgram(program_.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 6);
}

SlicePlane::SlicePlane(std::shared_ptr<const SliceVolume> volume, const PlaneSpec& spec, const SliceParams& params,
                       double maxAbsEigenvalue)
    : volume_(std::move(volume)),
      spec_(spec),
      quad_(planeQuad(volume_->volume(), spec)),
      params_(params),
      maxAbsEigenvalue_(maxAbsEigenvalue) {}

void SlicePlane::setSpec(const PlaneSpec& spec) {
  quad_ = planeQuad(volume_->volume(), spec);
  spec_ = spec;
}

double SlicePlane::depthOffsetWC(const FrameParams& p) const {
  if (!(params_.depthOffsetRadii > 0.0) || !(maxAbsEigenvalue_ > 0.0)) return 0.0;
  return params_.depthOffsetRadii * tensor::glyphRadiusWC(p.scale, p.sizing, maxAbsEigenvalue_);
}

void SlicePlane::drawOpaque(const Camera& cam, const FrameParams& p, std::uint32_t id, ContextTarget) {
  volume_->draw(cam, quad_, params_, depthOffsetWC(p), id);
}

std::pair<glm::dvec3, glm::dvec3> SlicePlane::boundsWC() const {
  glm::dvec3 lo = quad_.cornersWC[0], hi = lo;
  for (const glm::dvec3& c : quad_.cornersWC) {
    lo = glm::min(lo, c);
    hi = glm::max(hi, c);
  }
  return {lo, hi};
}

std::optional<double> SlicePlane::valueAt(const glm::dvec3& pointWC) const {
  // Onto the plane along its normal: a G-buffer point lies behind it by the depth offset.
  const glm::dvec3 onPlane = pointWC - glm::dot(pointWC - quad_.pointWC, quad_.normalWC) * quad_.normalWC;
  return volume_->volume().sample(onPlane, params_.linear);
}

std::optional<glm::dvec3> SlicePlane::trueSurface(const glm::dvec3& originWC, const glm::dvec3& dirWC) const {
  const double facing = glm::dot(dirWC, quad_.normalWC);
  if (facing == 0.0) return std::nullopt;  // edge on: the drawn point is as good
  const double t = glm::dot(quad_.pointWC - originWC, quad_.normalWC) / facing;
  if (!(t > 0.0)) return std::nullopt;
  return originWC + t * dirWC;
}

std::optional<UnderlayKey> SlicePlane::legendKey() const {
  const auto [lo, hi] = volume_->window(params_);
  return UnderlayKey{volume_->volume().name, params_.colormap, lo, hi};
}

std::size_t SlicePlane::gpuBytes() const {
  return volume_->gpuBytes() / std::size_t(std::max<long>(volume_.use_count(), 1));
}

}  // namespace tg::render
