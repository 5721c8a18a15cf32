#include "app/render_session.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <tuple>

#include "app/cli_common.h"
#include "app/color_array.h"
#include "app/field_flags.h"
#include "app/mesh_flags.h"
#include "app/names.h"
#include "app/scale/pipeline_calibration.h"
#include "app/slice_flags.h"
#include "app/tract_flags.h"
#include "render/legend/legend_pass.h"
#include "render/legend/legend_room.h"
#include "render/legend/orientation_pass.h"

namespace tg::app {

bool leavesLegendRoom(const RenderOptions& o, const render::FrameParams& p) {
  return p.legend.enabled && !o.eye && !o.ortho;
}

render::CameraDesc withLegendRoom(const RenderOptions& o, const render::FrameParams& p, const render::CameraDesc& desc,
                                  const std::vector<render::GlyphCell>& cells, const tensor::GlyphSet& set,
                                  const render::GlyphRenderer& r, const glm::dvec3& lo, const glm::dvec3& hi) {
  // What the legend pass will be given (GlyphRenderer::render): its panel's size.
  static_cast<void>(set);
  return render::frameBesideLegend(desc, o.width, o.height, lo, hi,
                                   render::drawnCellBoxes(cells, p.faMin, p.scale, p.sizing), p.legend,
                                   r.legendInputs(p));
}

RenderSession::RenderSession(const RenderOptions& o, Scene scene, std::vector<io::MeshData> meshes, bool keepGlyphs,
                             const char* command, const std::function<void(io::TensorField&)>& beforeUpload,
                             const util::ProgressSink& progress, const SessionHooks& hooks)
    : scene_(std::move(scene)), command_(command) {
  const auto t0 = Clock::now();
  glyphs_ = tensor::buildGlyphs(scene_.field.positions, scene_.field.tensors, scene_.field.ids, 0, o.field.glyph, progress);
  checkDrawable(glyphs_, scene_.field.path);
  const std::optional<ColorValues> colors =
      colorArrayValues(o.field.read.colorArray, scene_.field, glyphs_, scene_.colorVolume);
  scene_.colorVolume.reset();
  buildMs_ = msSince(t0);
  if (progress) progress("preparing", 0, 0, {});
  const tensor::FieldStats stats = sizingStats(scene_, glyphs_);
  magnitudes_ = sizingSample(scene_, stats);
  decideStressDefaults(scene_, stats);
  const tensor::ResolvedScale firstScale = tensor::resolveScale(sizingParams(o.field, scene_), magnitudes_);
  const Boxes first = boxes(firstScale);
  // The records go after the upload: a legend shown now needs its cells first.
  if (!keepGlyphs && leavesLegendRoom(o, frameParams(o, scene_, firstScale))) cells();
  std::optional<render::UnderlayVolume> underlay;
  if (o.slices.any()) {
    underlay = loadUnderlay(o.slices, scene_.field, command_);
    checkPlanes(o.slices, *underlay, command_);
    for (const std::string& w : underlayWarnings(o.slices, *underlay, first.glyphsWC.lo, first.glyphsWC.hi))
      std::fprintf(stderr, "tensorglyph %s: --underlay %s: %s\n", command_, printable(underlay->name).c_str(), printable(w).c_str());
    std::tie(underlayLoWC_, underlayHiWC_) = underlay->boundsWC();
    if (hooks.underlayLoaded) hooks.underlayLoaded(*underlay);
  }
  growByMeshes(meshes, meshLoWC_, meshHiWC_);
  std::vector<io::TractData> tracts = o.tracts.read(command_);
  growByTracts(tracts, meshLoWC_, meshHiWC_);
  // Each stage frees what the next no longer needs, so that peak memory
  // holds at most two copies of the glyphs (the records and the GL buffer).
  if (beforeUpload) beforeUpload(scene_.field);

  ctx_ = hooks.makeContext ? hooks.makeContext(o) : createContext(o.backend, o.width, o.height);
  lib_ = std::make_unique<gl::ShaderLibrary>();
  std::string path = sessionGlyphPath(o);
  if (path == kAutoPipeline) path = autoPipeline(o, frameParams(o, scene_, firstScale), hooks.alsoDraws);
  renderer_ = std::make_unique<render::GlyphRenderer>(
      ctx_->api(), *lib_, render::OverlayFactories{render::makeLegendPass, render::makeOrientationPass}, path);
  target_ = std::make_unique<render::GBuffer>(ctx_->api(), o.width, o.height);
  if (underlay)
    planes_ = addSlicePlanes(*renderer_, ctx_->api(), *lib_, o.slices, std::move(*underlay), glyphs_.maxAbsEigenvalue);
  const auto t1 = Clock::now();
  renderer_->upload(glyphs_);
  if (colors) renderer_->setColorScalars(colors->byRecord, colors->name);
  if (scene_.wholeField) renderer_->setColorRanges(scene_.wholeField->colors);
  // Before the meshes: the viewer finds its meshes as the last items.
  addTracts(*renderer_, ctx_->api(), *lib_, tracts, o.tracts.params);
  tracts.clear();
  addMeshes(*renderer_, ctx_->api(), *lib_, meshes, o.mesh.params);
  meshes.clear();
  ctx_->api().Finish();
  uploadMs_ = msSince(t1);
  glyphCount_ = glyphs_.glyphs.size();
  if (!keepGlyphs) glyphs_.glyphs = {};
}

std::string RenderSession::autoPipeline(const RenderOptions& o, const render::FrameParams& p,
                                        const std::vector<render::GlyphKind>& alsoDraws) {
  if (o.tessellate != 0) {
    pipelineWhy_ = "--pipeline auto: --tessellate draws on the raster path";
    return "raster";
  }
  // Glyphs below the FA threshold cost both paths little (culled first).
  const auto drawn = std::count_if(glyphs_.glyphs.begin(), glyphs_.glyphs.end(),
                                   [&](const tensor::GlyphRecord& g) { return double(g.fa) >= p.faMin; });
  CachedCalibration cached;
  const PathCalibration* cal = nullptr;
  if (choiceNeedsCalibration(p.glyph, alsoDraws)) {
    cached = calibrationFor(ctx_->api(), *lib_, currentCalibrationKey(ctx_->api()));
    if (!cached.said.empty() && !o.quiet)
      std::fprintf(stderr, "tensorglyph %s: --pipeline auto: %s\n", command_, printable(cached.said).c_str());
    cal = &cached.cal;
  }
  const PathChoice c = choosePath(cal, p.glyph, p.gamma, double(drawn), double(o.width) * double(o.height), alsoDraws);
  pipelineWhy_ = "--pipeline auto: " + c.why + (cached.file.empty() ? "" : "; calibration in " + printable(cached.file));
  return c.path;
}

// The GL objects below are deleted through this session's context, which
// must be current on the destroying thread: a Python Renderer may be reloaded
// or collected on another thread than the one that drew last, and GL calls
// with no current context crashed in Mesa.
RenderSession::~RenderSession() {
  if (!ctx_) return;
  try {
    ctx_->makeCurrent();
  } catch (const std::exception&) {
    // Their GL objects cannot be deleted without the context, and destroying
    // the context frees them: the wrappers are let go rather than crash.
    static_cast<void>(target_.release());
    static_cast<void>(renderer_.release());
    static_cast<void>(lib_.release());
  }
}

// The boxes are O(N) in the glyphs: computed again only when the scale
// changes, so redrawing for γ, colour or camera costs nothing here.
RenderSession::Boxes RenderSession::boxes(const tensor::ResolvedScale& sized) const {
  if (last_ && last_->scale == sized.scale && last_->mapping == sized.mapping) return *last_;
  if (glyphs_.glyphs.empty() && last_)
    throw std::logic_error("RenderSession::frame: a new scale needs the glyph records, which were dropped");
  Boxes b;
  b.scale = sized.scale;
  b.mapping = sized.mapping;
  b.glyphsWC = tensor::glyphBoxWC(glyphs_, sized.scale, sized.mapping);
  b.framing = tensor::framingBox(glyphs_, !scene_.field.grid, sized.typicalRadiusWC);
  last_ = b;
  return b;
}

const std::vector<render::GlyphCell>& RenderSession::cells() const {
  if (!cells_) {
    if (glyphs_.glyphs.empty() && glyphCount_ > 0)
      throw std::logic_error("RenderSession::frame: a legend's room needs the glyph records, which were dropped");
    cells_ = render::glyphCells(glyphs_);
  }
  return *cells_;
}

void RenderSession::setColorValues(std::span<const float> byInput, const std::string& option) {
  if (glyphs_.glyphs.empty() && glyphCount_ > 0)
    throw std::logic_error("RenderSession::setColorValues: the glyph records were dropped");
  const ColorValues v = colorValuesByInput(byInput, scene_.field.totalPoints, glyphs_, option);
  renderer_->setColorScalars(v.byRecord, v.name);
}

render::GBuffer& RenderSession::target(int width, int height) {
  if (target_->width() != width || target_->height() != height)
    target_ = std::make_unique<render::GBuffer>(ctx_->api(), width, height);
  return *target_;
}

void RenderSession::growForBlobs(glm::dvec3& lo, glm::dvec3& hi, const render::FrameParams& p) const {
  // A blob's surface reaches where its bump still adds, beyond the glyph box's corner.
  const double pad = render::kindPadWC(p, glyphs_.maxAbsEigenvalue);
  lo -= pad;
  hi += pad;
}

std::pair<glm::dvec3, glm::dvec3> RenderSession::depthBoxWC(const render::FrameParams& p) const {
  auto [lo, hi] = tensor::glyphBoxWC(glyphs_, p.scale, p.sizing);
  growForBlobs(lo, hi, p);
  growDepthRange(lo, hi, underlayLoWC_, underlayHiWC_);
  growDepthRange(lo, hi, meshLoWC_, meshHiWC_);
  return {lo, hi};
}

RenderSession::Frame RenderSession::frame(const RenderOptions& o) const {
  Frame f;
  f.sized = tensor::resolveScale(sizingParams(o.field, scene_), magnitudes_);
  const render::FrameParams& params = f.params = frameParams(o, scene_, f.sized);

  const Boxes b = boxes(f.sized);
  glm::dvec3 lo = b.glyphsWC.lo, hi = b.glyphsWC.hi;
  growForBlobs(lo, hi, params);
  // The camera's depth range holds the planes and meshes too (framing stays on the glyphs).
  growDepthRange(lo, hi, underlayLoWC_, underlayHiWC_);
  growDepthRange(lo, hi, meshLoWC_, meshHiWC_);
  // The GPU works in single precision: a box beyond FLT_MAX draws nothing.
  const double extent = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y),
                                  std::abs(hi.z)});
  if (!(extent <= double(FLT_MAX)))
    throw io::InputError(std::string(command_) + ": " + scene_.field.path +
                         ": the glyphs extend beyond the floating-point range (scale " + std::to_string(params.scale) +
                         ")");
  f.framing = b.framing;
  render::CameraDesc desc = chooseCamera(o, scene_, f.framing);
  if (leavesLegendRoom(o, params)) {
    const auto same = [&](const Room& r) {
      const render::CameraDesc& a = r.chosen;
      const render::FrameParams& q = r.params;
      return a.eyeWC == desc.eyeWC && a.lookAtWC == desc.lookAtWC && a.upWC == desc.upWC &&
             a.projection == desc.projection && a.fovYDeg == desc.fovYDeg && a.orthoHeight == desc.orthoHeight &&
             r.width == o.width && r.height == o.height && q.legend == params.legend && q.color == params.color &&
             q.colormap == params.colormap && q.colorWindow == params.colorWindow &&
             q.scale == params.scale && q.sizing == params.sizing && q.faMin == params.faMin &&
             r.keys == renderer_->legendKeys();
    };
    if (!room_ || !same(*room_))
      room_ = Room{desc, withLegendRoom(o, params, desc, cells(), glyphs_, *renderer_, lo, hi), o.width, o.height,
                   params, renderer_->legendKeys()};
    desc = room_->moved;
  }
  f.camera = render::makeCamera(desc, o.width, o.height, lo, hi);
  return f;
}

void RenderSession::draw(const Frame& f, const render::PassProgress& progress) {
  renderer_->render(f.camera, f.params, *target_, progress);
  ctx_->api().Finish();
}

render::FrameImage RenderSession::readback(const Frame& f, render::Channels channels) {
  return renderer_->readback(f.camera, *target_, channels);
}

}  // namespace tg::app
