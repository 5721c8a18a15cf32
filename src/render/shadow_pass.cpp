#include "render/shadow_pass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "render/glyph_path.h"
#include "shaders/lib/bindings.h"

namespace tg::render {
namespace {

struct Rect2 {
  glm::dvec2 lo{INFINITY}, hi{-INFINITY};
  void add(const glm::dvec2& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return !(lo.x <= hi.x && lo.y <= hi.y); }
};

// The view frustum's corners (WC) between view depths zNear and zFar.
std::array<glm::dvec3, 8> frustumCornersWC(const Camera& view, double zNear, double zFar) {
  const glm::dmat4 wcFromVC = glm::inverse(view.viewWCVC);
  const double aspect = double(view.width) / double(view.height);
  const bool persp = view.desc.projection == Projection::Perspective;
  const double t = persp ? std::tan(glm::radians(view.desc.fovYDeg) * 0.5) : 0.5 * view.desc.orthoHeight;
  std::array<glm::dvec3, 8> out;
  for (int k = 0; k < 8; ++k) {
    const double z = (k & 4) ? zFar : zNear, s = persp ? z : 1.0;
    const glm::dvec3 pVC((k & 1 ? 1 : -1) * t * aspect * s, (k & 2 ? 1 : -1) * t * s, -z);
    out[std::size_t(k)] = glm::dvec3(wcFromVC * glm::dvec4(pVC, 1.0));
  }
  return out;
}

// A square DEPTH32F texture, nearest-filtered, as the only attachment of a
// depth-only framebuffer: the map and the light's occluder depth alike.
void createDepthTarget(const gl::Api& gl, int size, GLuint& tex, GLuint& fbo, const char* what) {
  gl.CreateTextures(GL_TEXTURE_2D, 1, &tex);
  gl.TextureStorage2D(tex, 1, GL_DEPTH_COMPONENT32F, size, size);
  gl.TextureParameteri(tex, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TextureParameteri(tex, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.CreateFramebuffers(1, &fbo);
  gl.NamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, tex, 0);
  const GLenum none = GL_NONE;
  gl.NamedFramebufferDrawBuffers(fbo, 1, &none);
  if (gl.CheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string("ShadowPass: ") + what + " framebuffer incomplete");
}

void bindAndClearDepth(const gl::Api& gl, GLuint fbo, int size) {
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  gl.Viewport(0, 0, size, size);
  const float farDepth = 0.0f;  // reversed Z: nothing there
  gl.ClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &farDepth);
}

}  // namespace

Camera lightCamera(const Camera& view, const glm::dvec3& keyDirWC, const glm::dvec3& lo, const glm::dvec3& hi,
                   const ShadowParams& p) {
  const glm::dvec3 l = glm::normalize(keyDirWC);
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double r = std::max(0.5 * glm::length(hi - lo), 1e-30 + 1e-12 * glm::length(centre));
  const glm::dvec3 up = std::abs(l.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dmat4 lightView = glm::lookAt(centre + 2.0 * r * l, centre, up);
  auto lightXY = [&](const glm::dvec3& x) { return glm::dvec2(lightView * glm::dvec4(x, 1.0)); };
  Rect2 box, seen;
  double zMin = INFINITY, zMax = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 c((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
    box.add(lightXY(c));
    const double z = -(view.viewWCVC * glm::dvec4(c, 1.0)).z;
    zMin = std::min(zMin, z);
    zMax = std::max(zMax, z);
  }
  // Receivers are what the view sees of the box: within its frustum, cut at
  // the box's far side (a perspective frustum has no far plane).
  const bool persp = view.desc.projection == Projection::Perspective;
  const double zNear = persp ? std::max(view.nearVC, zMin) : view.nearVC;
  const double zFar = persp ? zMax : view.farVC;
  Rect2 region = box;
  if (zFar > zNear) {
    for (const glm::dvec3& c : frustumCornersWC(view, zNear, zFar)) seen.add(lightXY(c));
    Rect2 cut{glm::max(box.lo, seen.lo), glm::min(box.hi, seen.hi)};
    if (!cut.empty()) region = cut;
  }
  // 2% more on each side, so that the PCF taps of receivers at the edge of
  // the view still fall on the map.
  const glm::dvec2 mid = 0.5 * (region.lo + region.hi);
  const double side = std::max(1.04 * std::max(region.hi.x - region.lo.x, region.hi.y - region.lo.y), 1e-12 * r);
  const glm::dvec3 xAxis(lightView[0][0], lightView[1][0], lightView[2][0]);
  const glm::dvec3 yAxis(lightView[0][1], lightView[1][1], lightView[2][1]);
  const glm::dvec3 shift = mid.x * xAxis + mid.y * yAxis;
  CameraDesc d;
  d.projection = Projection::Orthographic;
  d.lookAtWC = centre + shift;
  d.eyeWC = d.lookAtWC + 2.0 * r * l;
  d.upWC = up;
  d.orthoHeight = side;
  int mapSize = p.mapSize;
  if (p.mapDensity > 0.0f) {
    // The view's pixel at the box centre's depth, in world units.
    const double zc = std::max(view.nearVC, -(view.viewWCVC * glm::dvec4(centre, 1.0)).z);
    const double pixel = (persp ? 2.0 * zc * std::tan(glm::radians(view.desc.fovYDeg) * 0.5)
                                : view.desc.orthoHeight) / double(view.height);
    const double texels = std::ceil(double(p.mapDensity) * side / pixel / 64.0) * 64.0;
    if (texels < double(mapSize)) mapSize = std::max(kMinShadowMapSize, int(texels));
  }
  return makeCamera(d, mapSize, mapSize, lo, hi);
}

ShadowPass::ShadowPass(const gl::Api& gl) : gl_(gl) {}

void ShadowPass::run(const PassFrame& f) {
  auto [lo, hi] = f.glyphs.castersBoxWC(f.p);
  // Context both casts and receives: the map covers it too.
  for (const auto& item : f.context)
    if (item->visible()) {
      const auto [itemLo, itemHi] = item->boundsWC();
      lo = glm::min(lo, itemLo);
      hi = glm::max(hi, itemHi);
    }
  const glm::dvec3 keyWC = glm::transpose(glm::dmat3(f.cam.viewWCVC)) * glm::dvec3(f.p.light.keyDirVC);
  light_ = lightCamera(f.cam, keyWC, lo, hi, f.p.shadow);
  f.glyphs.drawShadowCasters(light_, f.p, *this);
  drawContextOpaque(gl_, f.context, light_, f.p, ContextTarget::ShadowMap);
}

ShadowPass::~ShadowPass() {
  release();
  releaseOccluders();
}

void ShadowPass::releaseOccluders() {
  if (occluderFbo_) gl_.DeleteFramebuffers(1, &occluderFbo_);
  const GLuint tex[2] = {occluderDepth_, pyramid_};
  if (occluderDepth_) gl_.DeleteTextures(2, tex);
  occluderFbo_ = occluderDepth_ = pyramid_ = 0;
  occluderSize_ = 0;
}

void ShadowPass::beginOccluders(int mapSize) {
  if (mapSize != occluderSize_) {
    releaseOccluders();
    createDepthTarget(gl_, mapSize, occluderDepth_, occluderFbo_, "occluder");
    gl_.CreateTextures(GL_TEXTURE_2D, 1, &pyramid_);
    const int half = (mapSize + 1) / 2;
    gl_.TextureStorage2D(pyramid_, OccluderPyramid::levelsFor(mapSize, mapSize), GL_R32F, half, half);
    occluderSize_ = mapSize;
  }
  bindAndClearDepth(gl_, occluderFbo_, occluderSize_);
  gl::checkError(gl_, "ShadowPass::beginOccluders");
}

void ShadowPass::buildPyramid(const OccluderPyramid& pyramid) const {
  pyramid.build(occluderDepth_, pyramid_, occluderSize_, occluderSize_,
                OccluderPyramid::levelsFor(occluderSize_, occluderSize_));
}

void ShadowPass::release() {
  if (fbo_) gl_.DeleteFramebuffers(1, &fbo_);
  if (map_) gl_.DeleteTextures(1, &map_);
  fbo_ = map_ = 0;
  size_ = 0;
}

void ShadowPass::beginMap(int mapSize) {
  if (mapSize != size_) {
    release();
    GLint maxSize = 0;
    gl_.GetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (mapSize < kMinShadowMapSize || mapSize > std::min(maxSize, kMaxShadowMapSize))
      throw std::runtime_error("ShadowPass: shadow map size " + std::to_string(mapSize) + " outside " +
                               std::to_string(kMinShadowMapSize) + ".." +
                               std::to_string(std::min(maxSize, kMaxShadowMapSize)));
    createDepthTarget(gl_, mapSize, map_, fbo_, "shadow map");
    gl_.TextureParameteri(map_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.TextureParameteri(map_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    size_ = mapSize;
  }
  bindAndClearDepth(gl_, fbo_, size_);
  gl::checkError(gl_, "ShadowPass::beginMap");
}

void ShadowPass::bindForLighting(const gl::Program& prog, const Camera& view, const Camera& light,
                                 const ShadowParams& p, const GBuffer& target) const {
  gl_.BindTextureUnit(TG_UNIT_SHADOW_SCENE_DEPTH, target.depth());
  gl_.BindTextureUnit(TG_UNIT_SHADOW_MAP, map_);
  const double texel = light.desc.orthoHeight / double(size_);
  prog.set("uLightFromVC", glm::mat4(light.viewWCVC * glm::inverse(view.viewWCVC)));
  prog.set("uLightHalfExtent", float(0.5 * light.desc.orthoHeight));
  prog.set("uLightNearFar", glm::vec2(float(light.nearVC), float(light.farVC)));
  prog.set("uShadowMapSize", float(size_));
  prog.set("uShadowKernel", p.penumbra * float(size_));
  prog.set("uShadowBias", float(p.bias * texel));
  prog.set("uShadowNormalOffset", float(p.normalOffset * texel));
  prog.set("uShadowReceiverPlane", p.receiverPlane ? 1 : 0);
  prog.set("uShadowStrength", p.strength);
  gl::checkError(gl_, "ShadowPass::bindForLighting");
}

std::size_t ShadowPass::gpuBytes() const {
  std::size_t bytes = std::size_t(size_) * std::size_t(size_) * 4;
  if (occluderSize_ > 0) {
    const auto n = std::size_t(occluderSize_);
    bytes += n * n * 4;
    for (int l = 0; l < OccluderPyramid::levelsFor(occluderSize_, occluderSize_); ++l) {
      const std::size_t side = std::max<std::size_t>(1, ((n + 1) / 2) >> l);
      bytes += side * side * 4;
    }
  }
  return bytes;
}

}  // namespace tg::render
