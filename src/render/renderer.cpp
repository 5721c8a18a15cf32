#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string_view>

#include <glm/gtc/matrix_transform.hpp>

#include "render/camera_uniforms.h"
#include "render/color_readback.h"
#include "render/sprite_primitive.h"

namespace tg::render {

namespace {

std::string_view rendererName(const gl::Api& gl) {
  const auto* name = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
  return name ? name : "";
}

}  // namespace

GlyphRenderer::GlyphRenderer(const gl::Api& gl, const gl::ShaderLibrary& lib, OverlayFactory legend)
    : gl_(gl),
      lib_(lib),
      ellipsoid_(gl, lib,
                 {{GL_VERTEX_SHADER, glyphKind(GlyphKind::Ellipsoid).vertex},
                  {GL_FRAGMENT_SHADER, glyphKind(GlyphKind::Ellipsoid).fragment}}),
      lighting_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "lighting.frag"}}),
      profile_(RendererProfile::of(rendererName(gl))),
      sprites_(gl, profile_.glyphsPerSubmit),
      culling_(gl, lib),
      pyramid_(gl, lib),
      tessellated_(gl, lib),
      kinds_(gl, lib),
      makeLegend_(legend) {
  // The lighting pass's core-profile draw needs a vertex array object even
  // with no attributes.
  gl.CreateVertexArrays(1, &vao_);
  gl.CreateBuffers(1, &stats_);
  gl.NamedBufferStorage(stats_, 4 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
  GLfloat pointRange[2] = {0, 0};
  gl.GetFloatv(GL_POINT_SIZE_RANGE, pointRange);
  maxPointPx_ = double(pointRange[1]);
}

GlyphRenderer::~GlyphRenderer() {
  if (buffer_) gl_.DeleteBuffers(1, &buffer_);
  gl_.DeleteVertexArrays(1, &vao_);
  gl_.DeleteBuffers(1, &stats_);
}

void GlyphRenderer::upload(const tensor::GlyphSet& set) {
  if (set.glyphs.size() > std::size_t(INT32_MAX / 4))
    throw std::runtime_error("GlyphRenderer::upload: " + std::to_string(set.glyphs.size()) +
                             " glyphs; at most 2^29 fit gl_VertexID's four vertices per glyph");
  if (buffer_) gl_.DeleteBuffers(1, &buffer_);
  buffer_ = 0;
  count_ = GLsizei(set.glyphs.size());
  groupCounts_ = {set.sphereCount, set.definiteCount, set.glyphs.size() - set.sphereCount - set.definiteCount};
  mdMin_ = float(set.mdMin);
  mdMax_ = float(set.mdMax);
  centresLoWC_ = set.boundsMinWC;
  centresHiWC_ = set.boundsMaxWC;
  maxAbsEigenvalue_ = set.maxAbsEigenvalue;
  eigenMin_ = set.eigenvalueMin;
  eigenMax_ = set.eigenvalueMax;
  typicalDiameter_ = 1.0 / tensor::defaultScale(set, 1.0);
  for (const gl::Program* prog : glyphPrograms())
    if (prog) prog->set("uMdRange", glm::vec2(mdMin_, mdMax_));
  kinds_.setMdRange(glm::vec2(mdMin_, mdMax_));
  if (count_ > 0) {
    gl_.CreateBuffers(1, &buffer_);
    gl_.NamedBufferStorage(buffer_, GLsizeiptr(set.glyphs.size() * sizeof(tensor::GlyphRecord)),
                           set.glyphs.data(), 0);
  }
  culling_.upload(set, buffer_);
  gl::checkError(gl_, "GlyphRenderer::upload");
  ++uploads_;
}

void GlyphRenderer::setCamera(const gl::Program& prog, const Camera& cam) const { setCameraUniforms(prog, cam); }

// Null where a marching or tessellated program has not been built yet.
std::array<const gl::Program*, 9> GlyphRenderer::glyphPrograms() const {
  return {&ellipsoid_,      march_[0].get(), march_[1].get(), march_[2].get(),        march_[3].get(),
          march_[4].get(), march_[5].get(), tessellated_.program(), occluders_.get()};
}

std::array<const gl::Program*, 7> GlyphRenderer::shapePrograms() const {
  return {march_[0].get(), march_[1].get(), march_[2].get(),      march_[3].get(),
          march_[4].get(), march_[5].get(), tessellated_.program()};
}

void GlyphRenderer::setShapeUniforms(const gl::Program& prog, const FrameParams& p, const FrameParams* old) const {
  auto changed = [&](auto member) { return !old || !(old->*member == p.*member); };
  if (changed(&FrameParams::gamma)) prog.set("uGamma", float(p.gamma));
  if (changed(&FrameParams::march)) {
    prog.set("uMaxIterations", p.march.maxIterations);
    prog.set("uEpsilon", float(p.march.epsilon));
  }
}

// The Newton march, compiled the first time a frame has glyphs to march:
// ellipsoid, cylinder and box frames never build it (a third of the
// programs' compile time at start-up), and the counting variant only with
// --stats. Each variant is built only when a frame needs it.
const gl::Program& GlyphRenderer::marchProgram(bool stats, MarchVariant v, const FrameParams& p) {
  auto& slot = march_[std::size_t(2 * int(v) + (stats ? 1 : 0))];
  if (!slot) {
    const GlyphKindInfo& sq = glyphKind(GlyphKind::Superquadric);
    const auto stages = {gl::StageSource{GL_VERTEX_SHADER, sq.vertex}, gl::StageSource{GL_FRAGMENT_SHADER, sq.fragment}};
    // Program throws for an option no stage declares: a variant that is
    // missing fails here, loudly.
    std::vector<std::string_view> on;
    if (stats) on.push_back("TG_ITERATION_STATS");
    if (v == MarchVariant::Convex) on.push_back("TG_MARCH_CONVEX");
    if (v == MarchVariant::Mixed) on.push_back("TG_MARCH_MIXED");
    slot = std::make_unique<gl::Program>(gl_, lib_, stages, std::move(on));
    setGlyphUniforms(*slot, p, nullptr);
    setShapeUniforms(*slot, p, nullptr);
    slot->set("uMdRange", glm::vec2(mdMin_, mdMax_));
  }
  return *slot;
}

// The occlusion pre-pass's program, compiled on its first frame.
const gl::Program& GlyphRenderer::occluderProgram(const FrameParams& p) {
  if (!occluders_) {
    occluders_ = std::make_unique<gl::Program>(
        gl_, lib_,
        std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, "ellipsoid.vert"},
                                               {GL_FRAGMENT_SHADER, "occluder_disc.frag"}},
        std::vector<std::string_view>{"TG_OCCLUDER_DISC"});
    setGlyphUniforms(*occluders_, p, nullptr);
    occluders_->set("uOccluders", 0);  // it builds the pyramid
  }
  return *occluders_;
}

// The tessellated baseline's program, compiled on its first frame, as the march's.
const gl::Program& GlyphRenderer::tessellatedProgram(const FrameParams& p) {
  if (!tessellated_.program()) {
    const gl::Program& prog = tessellated_.build();
    setGlyphUniforms(prog, p, nullptr);
    setShapeUniforms(prog, p, nullptr);
    prog.set("uMdRange", glm::vec2(mdMin_, mdMax_));
  }
  return *tessellated_.program();
}

void GlyphRenderer::setParams(const FrameParams& p) {
  const FrameParams* old = params_ ? &*params_ : nullptr;
  auto changed = [&](auto member) { return !old || !(old->*member == p.*member); };
  for (const gl::Program* prog : glyphPrograms())
    if (prog) setGlyphUniforms(*prog, p, old);
  kinds_.setParams(p, old);
  for (const gl::Program* prog : shapePrograms())
    if (prog) setShapeUniforms(*prog, p, old);
  if (changed(&FrameParams::background)) {
    lighting_.set("uBackground", p.background);
    if (lightingVariant_) lightingVariant_->set("uBackground", p.background);
  }
  if (changed(&FrameParams::light)) {
    setLighting(lighting_, p);
    if (lightingVariant_) setLighting(*lightingVariant_, p);
  }
  params_ = p;
}

void GlyphRenderer::setLighting(const gl::Program& prog, const FrameParams& p) const {
  prog.set("uKeyDirVC", p.light.keyDirVC);
  prog.set("uLightMix", glm::vec4(p.light.ambient, p.light.head, p.light.key, p.light.specular));
  prog.set("uShininess", p.light.shininess);
}

// The plain program unless an effect needs a variant, which is compiled on
// first use: with every effect off the frame runs main's exact shader. Only
// the variant in use is kept, so that an effect switched off holds nothing.
const gl::Program& GlyphRenderer::lightingFor(const FrameParams& p, bool shadows) {
  const int key = (p.ao.enabled ? 1 : 0) | (shadows ? 2 : 0);
  if (key == 0) {
    lightingVariant_.reset();
    return lighting_;
  }
  if (!lightingVariant_ || lightingVariantKey_ != key) {
    std::vector<std::string_view> on;
    if (key & 1) on.push_back("TG_AO");
    if (key & 2) on.push_back("TG_SHADOWS");
    lightingVariant_ = std::make_unique<gl::Program>(
        gl_, lib_,
        std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, "fullscreen.vert"},
                                               {GL_FRAGMENT_SHADER, "lighting.frag"}},
        std::move(on));
    lightingVariantKey_ = key;
    lightingVariant_->set("uBackground", p.background);
    setLighting(*lightingVariant_, p);
  }
  return *lightingVariant_;
}

ContextItem& GlyphRenderer::addContext(std::unique_ptr<ContextItem> item) {
  if (!item) throw std::invalid_argument("GlyphRenderer::addContext: no item");
  if (context_.size() >= kMaxContextItems)
    throw std::invalid_argument("GlyphRenderer::addContext: at most " + std::to_string(kMaxContextItems) +
                                " context items");
  context_.push_back(std::move(item));
  return *context_.back();
}

std::vector<UnderlayKey> GlyphRenderer::legendKeys() const {
  std::vector<UnderlayKey> keys;
  for (const auto& item : context_) {
    const std::optional<UnderlayKey> key = item->visible() ? item->legendKey() : std::nullopt;
    if (key && std::find(keys.begin(), keys.end(), *key) == keys.end()) keys.push_back(*key);
  }
  return keys;
}

ContextItem* GlyphRenderer::contextItem(std::uint32_t id) const {
  if (!isContextId(id) || id - kContextIdBase >= context_.size()) return nullptr;
  return context_[id - kContextIdBase].get();
}

void GlyphRenderer::drawContext(const Camera& cam, const FrameParams& p, ContextTarget target) const {
  if (context_.empty()) return;
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_GREATER);  // reversed Z
  gl_.DepthMask(GL_TRUE);
  for (std::size_t i = 0; i < context_.size(); ++i)
    if (context_[i]->visible()) context_[i]->drawOpaque(cam, p, kContextIdBase + std::uint32_t(i), target);
}

double GlyphRenderer::aoRadiusWC(const FrameParams& p) const {
  return p.ao.radius > 0.0 ? p.ao.radius : AoParams::kAutoRadius * typicalDiameter_ * p.scale;
}

Camera GlyphRenderer::renderShadowMap(const Camera& cam, const FrameParams& p, int split) {
  if (!shadow_) {
    shadow_ = std::make_unique<ShadowPass>(gl_);
  }
  // Casters: the selected centres, grown by the largest glyph box's half
  // diagonal (a superquadric reaches its box's corners).
  glm::dvec3 lo = centresLoWC_, hi = centresHiWC_;
  if (p.slab.axis >= 0) {
    const int a = p.slab.axis;
    lo[a] = std::max(lo[a], p.slab.lo);
    hi[a] = std::max(lo[a], std::min(hi[a], p.slab.hi));
  }
  const double pad = tensor::kGlyphReach * tensor::glyphRadiusWC(p.scale, p.sizing, maxAbsEigenvalue_);
  lo -= pad;
  hi += pad;
  // Context both casts and receives: the map covers it too.
  for (const auto& item : context_)
    if (item->visible()) {
      const auto [itemLo, itemHi] = item->boundsWC();
      lo = glm::min(lo, itemLo);
      hi = glm::max(hi, itemHi);
    }
  const glm::dvec3 keyWC = glm::transpose(glm::dmat3(cam.viewWCVC)) * glm::dvec3(p.light.keyDirVC);
  const Camera light = lightCamera(cam, keyWC, lo, hi, p.shadow);
  const bool tessellated = p.tessellation > 0;
  if (tessellated) culling_.bypass();
  else culling_.prepare(light, p.scale, p.sizing, p.faMin, p.slab, p.frustumCulling, pointSprites(light, p));
  beginGlyphs();
  // The view's occlusion pre-pass, from the light: the march is most of the map's cost.
  const bool occluders = !tessellated && split < 3 && p.occlusionPrepass && hasOccluders();
  if (occluders) {
    shadow_->beginOccluders(light.width);
    useGlyphProgram(occluderProgram(p), light);
    culling_.draw(sprites_, 0, 2);
    shadow_->buildPyramid(pyramid_);
  }
  shadow_->beginMap(light.width);
  // The glyph programs themselves, from the light: the same exact surfaces.
  if (count_ > 0) drawGlyphs(light, p, split, false, occluders);
  drawContext(light, p, ContextTarget::ShadowMap);
  ++shadowMapPasses_;
  return light;
}

bool GlyphRenderer::pointSprites(const Camera& cam, const FrameParams& p) const {
  const double maxRadiusWC = tensor::glyphRadiusWC(p.scale, p.sizing, maxAbsEigenvalue_);
  if (!p.pointSprites ||
      !pointSpritesFit(cam, centresLoWC_, centresHiWC_, tensor::kGlyphReach * maxRadiusWC, maxPointPx_))
    return false;
  // Wide ray-cast glyphs pay for quads' three more vertex runs with the
  // fragments that their own axes save (closed-form kinds keep axis-aligned quads).
  return !(p.orientedSprites && glyphKind(p.glyph).draw != KindDraw::ClosedForm && typicalPx(cam, p) >= profile_.orientedQuadMinPx);
}

double GlyphRenderer::typicalPx(const Camera& cam, const FrameParams& p) const {
  const double maxRadiusWC = tensor::glyphRadiusWC(p.scale, p.sizing, maxAbsEigenvalue_);
  const double typicalWC = std::min(typicalDiameter_ * p.scale, 2.0 * maxRadiusWC);
  return typicalSpritePx(cam, centresLoWC_, centresHiWC_, typicalWC);
}

void GlyphRenderer::beginGlyphs() const {
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_GREATER);  // reversed Z
  gl_.DepthMask(GL_TRUE);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer_);
}

void GlyphRenderer::useGlyphProgram(const gl::Program& prog, const Camera& cam) const {
  setCamera(prog, cam);
  prog.set("uCompacted", culling_.compacted() ? 1 : 0);
  prog.set("uPointSprites", culling_.pointSprites() ? 1 : 0);
  prog.set("uOrientedSprites", params_ && params_->orientedSprites ? 1 : 0);
  gl_.UseProgram(prog.id());
}

// Dispatch (README, "How glyphs are dispatched") over the groups
// (tensor::GlyphGroup): the ellipsoid program draws groups [0, split), the
// marching program the rest. At gamma 0 only mixed-sign glyphs are not
// ellipsoids; at gamma > 0 only spheres are.
void GlyphRenderer::drawGlyphs(const Camera& cam, const FrameParams& p, int split, bool stats, bool occluders) {
  if (p.tessellation > 0) {
    setCamera(tessellatedProgram(p), cam);
    tessellated_.draw(p.tessellation, std::size_t(count_));
    return;
  }
  if (glyphKind(p.glyph).draw == KindDraw::ClosedForm) {
    // Every group by the kind's own program: no ellipsoid, no march.
    useGlyphProgram(kinds_.program(p.glyph, p), cam);
    culling_.draw(sprites_, 0, 3);
    return;
  }
  // The pre-pass drew these very ellipsoids (groups below split): the
  // hidden ones stop in the vertex stage.
  ellipsoid_.set("uOccluders", occluders ? 1 : 0);
  useGlyphProgram(ellipsoid_, cam);
  culling_.draw(sprites_, 0, split);
  // Marched groups: definite glyphs (marched at gamma > 0, all convex) by
  // the convex variant, mixed-sign ones by the mixed variant, or all by the
  // general march; a group with no glyphs builds no program.
  const int definite = int(tensor::GlyphGroup::Definite), mixed = int(tensor::GlyphGroup::Mixed);
  const bool convex = p.marchVariants && split == definite;
  auto march = [&](MarchVariant v, int g0, int g1) {
    const gl::Program& prog = marchProgram(stats, v, p);
    // Per pass, from what ran: the shaders never read a stale pre-pass.
    prog.set("uOccluders", occluders ? 1 : 0);
    useGlyphProgram(prog, cam);
    culling_.draw(sprites_, g0, g1);
    ++marchDraws_[std::size_t(v)];
  };
  if (convex && groupCounts_[std::size_t(definite)] > 0) march(MarchVariant::Convex, definite, definite + 1);
  const int rest = convex ? mixed : split;
  if (p.marchVariants && rest == mixed) {
    if (groupCounts_[std::size_t(mixed)] > 0) march(MarchVariant::Mixed, mixed, mixed + 1);
  } else if (rest < 3) {
    march(MarchVariant::General, rest, 3);
  }
}

void GlyphRenderer::render(const Camera& cam, const FrameParams& p, const GBuffer& target) {
  if (!params_ || !(*params_ == p)) setParams(p);
  gl_.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  const bool tessellated = p.tessellation > 0;
  const bool sq = glyphKind(p.glyph).draw == KindDraw::Superquadric;
  // split 3: nothing marches (ellipsoids, and the closed-form kinds: no pre-pass).
  const int split = !sq ? 3 : p.gamma > 0.0 ? 1 : 2;
  // The shadow map first, so that culling is left prepared for the view.
  std::optional<Camera> light;
  if (!p.shadow.enabled) shadow_.reset();
  else if (count_ > 0 || !context_.empty()) light = renderShadowMap(cam, p, split);
  const double typical = typicalPx(cam, p);
  if (tessellated) culling_.bypass();
  else culling_.prepare(cam, p.scale, p.sizing, p.faMin, p.slab, p.frustumCulling, pointSprites(cam, p),
                        p.pixelCull && typical < profile_.pixelCullMaxPx);
  if (count_ > 0) beginGlyphs();
  const bool marching = count_ > 0 && !tessellated && split < 3;
  // Only mixed-sign glyphs (a stress field) give no occluders: no pre-pass;
  // nor do glyphs too small for it to pay (render/sprite_primitive.h).
  const bool occluders = marching && p.occlusionPrepass && hasOccluders() && !(typical < profile_.occlusionMinPx);
  if (occluders) {
    // Occlusion pre-pass: the ellipsoids of spheres and definite glyphs,
    // depth only, each its outline at the farthest depth of its silhouette
    // contour, behind every front hit. Their superquadrics hold them, so no
    // visible surface lies behind this depth: spheres and superquadrics
    // wholly behind it are culled, and pixels whose box entry is behind it
    // skip the march (shaders/lib/occlusion.glsl). An occluder fragment
    // reads five inputs and casts no ray, so the pass costs about what its
    // sprites' setup does.
    target.beginOccluders();
    useGlyphProgram(occluderProgram(p), cam);
    culling_.draw(sprites_, 0, 2);
    pyramid_.build(target);
    ++occlusionPrepasses_;
  }
  target.beginGeometry();
  if (count_ > 0) {
    if (p.iterationStats && !tessellated) {
      const GLuint zero[4] = {0, 0, 0, 0};
      gl_.NamedBufferSubData(stats_, 0, sizeof(zero), zero);
      gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, stats_);
    }
    drawGlyphs(cam, p, split, p.iterationStats, occluders);
  }
  drawContext(cam, p, ContextTarget::View);
  gl_.Disable(GL_DEPTH_TEST);
  if (p.ao.enabled) {
    if (!ao_) ao_ = std::make_unique<AoPass>(gl_, lib_);
    ao_->run(cam, target, p.ao, aoRadiusWC(p));
  }
  const gl::Program& lighting = lightingFor(p, light.has_value());
  // Shadows sample the G-buffer depth: it cannot be the attachment too.
  if (light) target.beginLighting();
  else target.beginLightingCovered(&p.background[0]);
  setCamera(lighting, cam);
  if (light) shadow_->bindForLighting(lighting, cam, *light, p.shadow, target);
  gl_.UseProgram(lighting.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  target.endLighting();
  for (const auto& item : context_)
    if (item->visible() && item->translucent()) item->drawTranslucent(cam, p, target);
  if (p.outline.enabled) {
    if (!outline_) outline_ = std::make_unique<OutlinePass>(gl_, lib_);
    setCameraUniforms(outline_->program(), cam);
    outline_->run(target, p.outline);
  }
  // Last before readback: the legend draws over every effect.
  if (p.legend.enabled) {
    if (!makeLegend_) throw std::invalid_argument("GlyphRenderer::render: this program has no legend pass");
    if (!legend_) legend_ = makeLegend_(gl_, lib_);
    legend_->draw(cam, p, {mdMin_, mdMax_, eigenMin_, eigenMax_, legendKeys()});
  } else {
    legend_.reset();
  }
  gl::checkError(gl_, "GlyphRenderer::render");
}

namespace {

// GL rows run bottom-up; FrameImage rows top-down.
template <class T>
void flipRows(std::vector<T>& v, int width, int height, int channels) {
  const std::size_t row = std::size_t(width) * channels;
  for (int j = 0; j < height / 2; ++j)
    std::swap_ranges(v.begin() + std::ptrdiff_t(j * row), v.begin() + std::ptrdiff_t((j + 1) * row),
                     v.begin() + std::ptrdiff_t((height - 1 - j) * row));
}

}  // namespace

std::size_t GlyphRenderer::gpuBytes() const {
  return std::size_t(count_) * sizeof(tensor::GlyphRecord) + culling_.gpuBytes() + tessellated_.meshBytes() +
         (legend_ ? legend_->gpuBytes() : 0) +
         (ao_ ? ao_->gpuBytes() : 0) + (shadow_ ? shadow_->gpuBytes() : 0) + contextBytes();
}

std::size_t GlyphRenderer::contextBytes() const {
  std::size_t bytes = 0;
  for (const auto& item : context_) bytes += item->gpuBytes();
  return bytes;
}

IterationStats GlyphRenderer::iterationStats() const {
  GLuint v[4] = {0, 0, 0, 0};
  gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl_.GetNamedBufferSubData(stats_, 0, sizeof(v), v);
  gl::checkError(gl_, "GlyphRenderer::iterationStats");
  IterationStats s;
  s.pixels = v[2];
  s.gaugeCalls = v[3];
  s.max = v[1];
  s.mean = v[2] ? double(v[0]) / v[2] : 0.0;
  return s;
}

// Reads each channel straight into its final array: no staging copies, so a
// PNG frame costs 16 bytes per pixel on the CPU and an EXR frame 36.
FrameImage GlyphRenderer::readback(const Camera& cam, const GBuffer& t, Channels channels) const {
  FrameImage img;
  const int w = t.width(), h = t.height();
  img.width = w;
  img.height = h;
  const std::size_t n = std::size_t(w) * h;
  auto bytes = [](const auto& v) { return GLsizei(v.size() * sizeof(v[0])); };
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  if (channels == Channels::Rgba8) {
    img.rgba8 = readColorRgba8(gl_, t);
    return img;
  }
  img.rgba.resize(4 * n);
  gl_.GetTextureImage(t.color(), 0, GL_RGBA, GL_FLOAT, bytes(img.rgba), img.rgba.data());
  flipRows(img.rgba, w, h, 4);
  if (channels == Channels::All) {
    img.id.resize(n);
    img.depth.resize(n);
    img.normalWC.resize(3 * n);
    gl_.GetTextureImage(t.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, bytes(img.id), img.id.data());
    gl_.GetTextureImage(t.depth(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, bytes(img.depth), img.depth.data());
    gl_.GetTextureImage(t.normalWC(), 0, GL_RGB, GL_FLOAT, bytes(img.normalWC), img.normalWC.data());
    flipRows(img.id, w, h, 1);
    flipRows(img.depth, w, h, 1);
    flipRows(img.normalWC, w, h, 3);
    for (std::size_t i = 0; i < n; ++i) {
      const bool empty = img.id[i] == 0xFFFFFFFFu;
      img.depth[i] = empty ? INFINITY : float(cam.viewDepthFromWindowDepth(img.depth[i]));
      if (empty) img.normalWC[3 * i] = img.normalWC[3 * i + 1] = img.normalWC[3 * i + 2] = 0.0f;
    }
  }
  gl::checkError(gl_, "GlyphRenderer::readback");
  return img;
}

}  // namespace tg::render
