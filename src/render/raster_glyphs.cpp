#include "render/raster_glyphs.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "render/camera_uniforms.h"
#include "render/compute_glyphs.h"
#include "render/cpu_glyphs.h"
#include "render/march_groups.h"
#include "render/shadow_pass.h"
#include "render/sprite_primitive.h"
#include "shaders/lib/bindings.h"

namespace tg::render {

namespace {

std::string_view rendererName(const gl::Api& gl) {
  const auto* name = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
  return name ? name : "";
}

// Blobs need every bump a pixel's ray meets, which no one glyph's sprite has.
void refuseBlobs(const FrameParams& p) {
  if (glyphKind(p.glyph).draw == KindDraw::Blob)
    throw std::invalid_argument("GlyphRenderer::render: the raster glyph path casts no blobs (each pixel needs every "
                                "bump its ray meets); use the cpu path");
}

}  // namespace

RasterGlyphs::RasterGlyphs(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl),
      lib_(lib),
      ellipsoid_(gl, lib,
                 {{GL_VERTEX_SHADER, glyphKind(GlyphKind::Ellipsoid).vertex},
                  {GL_FRAGMENT_SHADER, glyphKind(GlyphKind::Ellipsoid).fragment}}),
      profile_(RendererProfile::of(rendererName(gl))),
      sprites_(gl, profile_.glyphsPerSubmit),
      culling_(gl, lib),
      pyramid_(gl, lib),
      tessellated_(gl, lib),
      kinds_(gl, lib) {
  gl.CreateBuffers(1, &stats_);
  gl.NamedBufferStorage(stats_, 4 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
  GLfloat pointRange[2] = {0, 0};
  gl.GetFloatv(GL_POINT_SIZE_RANGE, pointRange);
  maxPointPx_ = double(pointRange[1]);
}

RasterGlyphs::~RasterGlyphs() {
  if (buffer_) gl_.DeleteBuffers(1, &buffer_);
  if (scalars_) gl_.DeleteBuffers(1, &scalars_);
  gl_.DeleteBuffers(1, &stats_);
}

void RasterGlyphs::upload(const tensor::GlyphSet& set) {
  if (set.glyphs.size() > std::size_t(INT32_MAX / 4))
    throw std::runtime_error("GlyphRenderer::upload: " + std::to_string(set.glyphs.size()) +
                             " glyphs; at most 2^29 fit gl_VertexID's four vertices per glyph");
  if (buffer_) gl_.DeleteBuffers(1, &buffer_);
  if (scalars_) gl_.DeleteBuffers(1, &scalars_);
  buffer_ = scalars_ = 0;
  count_ = GLsizei(set.glyphs.size());
  groupCounts_ = {set.sphereCount, set.definiteCount, set.glyphs.size() - set.sphereCount - set.definiteCount};
  centresLoWC_ = set.boundsMinWC;
  centresHiWC_ = set.boundsMaxWC;
  maxAbsEigenvalue_ = set.maxAbsEigenvalue;
  typicalDiameter_ = 1.0 / tensor::defaultScale(set, 1.0);
  if (count_ > 0) {
    gl_.CreateBuffers(1, &buffer_);
    gl_.NamedBufferStorage(buffer_, GLsizeiptr(set.glyphs.size() * sizeof(tensor::GlyphRecord)),
                           set.glyphs.data(), 0);
    ++recordUploads_;
  }
  culling_.upload(set, buffer_);
  gl::checkError(gl_, "GlyphRenderer::upload");
}

void RasterGlyphs::setColorWindow(glm::dvec2 window) {
  const glm::vec2 w(window);
  if (w == colorWindow_) return;
  colorWindow_ = w;
  for (const gl::Program* prog : glyphPrograms())
    if (prog) prog->set("uColorWindow", colorWindow_);
  kinds_.setColorWindow(colorWindow_);
}

void RasterGlyphs::uploadColorScalars(std::span<const float> byRecord) {
  if (byRecord.size() != std::size_t(count_))
    throw std::invalid_argument("GlyphRenderer::setColorScalars: " + std::to_string(byRecord.size()) +
                                " values for " + std::to_string(count_) + " glyphs");
  if (scalars_) gl_.DeleteBuffers(1, &scalars_);
  scalars_ = 0;
  if (count_ > 0) {
    gl_.CreateBuffers(1, &scalars_);
    gl_.NamedBufferStorage(scalars_, GLsizeiptr(byRecord.size_bytes()), byRecord.data(), 0);
  }
  gl::checkError(gl_, "GlyphRenderer::setColorScalars");
}

// Null where a marching or tessellated program has not been built yet.
std::array<const gl::Program*, 9> RasterGlyphs::glyphPrograms() const {
  return {&ellipsoid_,      march_[0].get(), march_[1].get(), march_[2].get(),        march_[3].get(),
          march_[4].get(), march_[5].get(), tessellated_.program(), occluders_.get()};
}

std::array<const gl::Program*, 7> RasterGlyphs::shapePrograms() const {
  return {march_[0].get(), march_[1].get(), march_[2].get(),      march_[3].get(),
          march_[4].get(), march_[5].get(), tessellated_.program()};
}

bool RasterGlyphs::marchProgramBuilt() const {
  return std::any_of(march_.begin(), march_.end(), [](const auto& m) { return m != nullptr; });
}

void RasterGlyphs::setShapeUniforms(const gl::Program& prog, const FrameParams& p, const FrameParams* old) const {
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
const gl::Program& RasterGlyphs::marchProgram(bool stats, MarchVariant v, const FrameParams& p) {
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
    slot->set("uColorWindow", colorWindow_);
  }
  return *slot;
}

// The occlusion pre-pass's program, compiled on its first frame.
const gl::Program& RasterGlyphs::occluderProgram(const FrameParams& p) {
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
const gl::Program& RasterGlyphs::tessellatedProgram(const FrameParams& p) {
  if (!tessellated_.program()) {
    const gl::Program& prog = tessellated_.build();
    setGlyphUniforms(prog, p, nullptr);
    setShapeUniforms(prog, p, nullptr);
    prog.set("uColorWindow", colorWindow_);
  }
  return *tessellated_.program();
}

void RasterGlyphs::setParams(const FrameParams& p, const FrameParams* old) {
  for (const gl::Program* prog : glyphPrograms())
    if (prog) setGlyphUniforms(*prog, p, old);
  kinds_.setParams(p, old);
  for (const gl::Program* prog : shapePrograms())
    if (prog) setShapeUniforms(*prog, p, old);
  orientedSprites_ = p.orientedSprites;
}

std::pair<glm::dvec3, glm::dvec3> castersBoxWC(const glm::dvec3& centresLoWC, const glm::dvec3& centresHiWC,
                                               double maxAbsEigenvalue, const FrameParams& p) {
  // The selected centres, grown by the largest glyph box's half diagonal (a
  // superquadric reaches its box's corners).
  glm::dvec3 lo = centresLoWC, hi = centresHiWC;
  // A slab across a world axis cuts the box; an oblique one leaves it whole.
  if (p.slab.axis >= 0 && p.slab.normalWC == glm::dvec3(0.0)) {
    const int a = p.slab.axis;
    lo[a] = std::max(lo[a], p.slab.lo);
    hi[a] = std::max(lo[a], std::min(hi[a], p.slab.hi));
  }
  const double pad = kindReach(p) * tensor::glyphRadiusWC(p.scale, p.sizing, maxAbsEigenvalue);
  return {lo - pad, hi + pad};
}

std::pair<glm::dvec3, glm::dvec3> RasterGlyphs::castersBoxWC(const FrameParams& p) const {
  return render::castersBoxWC(centresLoWC_, centresHiWC_, maxAbsEigenvalue_, p);
}

void RasterGlyphs::drawShadowCasters(const Camera& light, const FrameParams& p, ShadowPass& shadow) {
  refuseBlobs(p);
  const int split = marchSplit(p);
  const bool tessellated = p.tessellation > 0;
  if (tessellated) culling_.bypass();
  else culling_.prepare(light, p.scale, p.sizing, p.faMin, p.slab, p.frustumCulling, pointSprites(light, p));
  beginGlyphs();
  // The view's occlusion pre-pass, from the light: the march is most of the map's cost.
  const bool occluders = !tessellated && split < 3 && p.occlusionPrepass && hasOccluders();
  if (occluders) {
    shadow.beginOccluders(light.width);
    useGlyphProgram(occluderProgram(p), light);
    culling_.draw(sprites_, 0, 2);
    shadow.buildPyramid(pyramid_);
  }
  shadow.beginMap(light.width);
  // The glyph programs themselves, from the light: the same exact surfaces.
  if (count_ > 0) drawGlyphs(light, p, split, false, occluders);
}

bool RasterGlyphs::pointSprites(const Camera& cam, const FrameParams& p) const {
  const double maxRadiusWC = tensor::glyphRadiusWC(p.scale, p.sizing, maxAbsEigenvalue_);
  if (!p.pointSprites ||
      !pointSpritesFit(cam, centresLoWC_, centresHiWC_, tensor::kGlyphReach * maxRadiusWC, maxPointPx_))
    return false;
  // Wide ray-cast glyphs pay for quads' three more vertex runs with the
  // fragments that their own axes save (closed-form kinds keep axis-aligned quads).
  return !(p.orientedSprites && glyphKind(p.glyph).draw != KindDraw::ClosedForm &&
           typicalPx(cam, p) >= profile_.orientedQuadMinPx);
}

double RasterGlyphs::typicalPx(const Camera& cam, const FrameParams& p) const {
  const double maxRadiusWC = tensor::glyphRadiusWC(p.scale, p.sizing, maxAbsEigenvalue_);
  const double typicalWC = std::min(typicalDiameter_ * p.scale, 2.0 * maxRadiusWC);
  return typicalSpritePx(cam, centresLoWC_, centresHiWC_, typicalWC);
}

void RasterGlyphs::beginGlyphs() const {
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_GREATER);  // reversed Z
  gl_.DepthMask(GL_TRUE);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_GLYPHS, buffer_);
  if (scalars_) gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_COLOR_SCALARS, scalars_);
}

void RasterGlyphs::useGlyphProgram(const gl::Program& prog, const Camera& cam) const {
  setCameraUniforms(prog, cam);
  prog.set("uCompacted", culling_.compacted() ? 1 : 0);
  prog.set("uPointSprites", culling_.pointSprites() ? 1 : 0);
  prog.set("uOrientedSprites", orientedSprites_ ? 1 : 0);
  gl_.UseProgram(prog.id());
}

// Dispatch (docs/design.md, "How glyphs are dispatched") over the groups
// (tensor::GlyphGroup) by the kind's row (render/glyph_kind.h): the
// ellipsoid program draws groups [0, split), the marching program the rest.
// At gamma 0 only mixed-sign glyphs are not ellipsoids; at gamma > 0 only
// spheres are.
void RasterGlyphs::drawGlyphs(const Camera& cam, const FrameParams& p, int split, bool stats, bool occluders) {
  if (p.tessellation > 0) {
    setCameraUniforms(tessellatedProgram(p), cam);
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
  const bool convex = marchVariant(definite, split, p.marchVariants) == MarchVariant::Convex;
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
  if (rest == mixed && marchVariant(mixed, split, p.marchVariants) == MarchVariant::Mixed) {
    if (groupCounts_[std::size_t(mixed)] > 0) march(MarchVariant::Mixed, mixed, mixed + 1);
  } else if (rest < 3) {
    march(MarchVariant::General, rest, 3);
  }
}

void RasterGlyphs::drawView(const Camera& cam, const FrameParams& p, const GBuffer& target) {
  refuseBlobs(p);
  const bool tessellated = p.tessellation > 0;
  const int split = marchSplit(p);
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
      gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_ITERATION_STATS, stats_);
    }
    drawGlyphs(cam, p, split, p.iterationStats, occluders);
  }
}

std::size_t RasterGlyphs::gpuBytes() const {
  return std::size_t(count_) * (sizeof(tensor::GlyphRecord) + (scalars_ ? sizeof(float) : 0)) + culling_.gpuBytes() +
         tessellated_.meshBytes();
}

IterationStats RasterGlyphs::iterationStats() const {
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

std::unique_ptr<GlyphPath> makeGlyphPath(std::string_view name, const gl::Api& gl, const gl::ShaderLibrary& lib) {
  if (name == "raster") return std::make_unique<RasterGlyphs>(gl, lib);
  if (name == "cpu") return std::make_unique<CpuGlyphs>(gl, lib);
  if (name == "compute") return std::make_unique<ComputeGlyphs>(gl, lib);
  throw std::invalid_argument("makeGlyphPath: unknown glyph path \"" + std::string(name) + "\"; choose " +
                              glyphPathNames());
}

std::string glyphPathNames() {
  std::string names;
  for (const std::string_view n : kGlyphPathNames) names += (names.empty() ? "" : ", ") + std::string(n);
  return names;
}

}  // namespace tg::render
