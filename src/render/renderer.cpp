#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "render/antialias_pass.h"
#include "render/ao_pass.h"
#include "render/color_readback.h"
#include "render/outline_pass.h"
#include "render/shadow_pass.h"
#include "render/color_scalar.h"
#include "shaders/lib/bindings.h"
#include "tensor/glyph_scale.h"

namespace tg::render {

namespace {

template <class Pass>
std::unique_ptr<FramePass> make(const gl::Api& gl, const gl::ShaderLibrary& lib) {
  return std::make_unique<Pass>(gl, lib);
}

std::unique_ptr<FramePass> makeShadow(const gl::Api& gl, const gl::ShaderLibrary&) {
  return std::make_unique<ShadowPass>(gl);
}

}  // namespace

GlyphRenderer::GlyphRenderer(const gl::Api& gl, const gl::ShaderLibrary& lib, OverlayFactories overlays,
                             std::string_view glyphPath)
    : GlyphRenderer(gl, lib, overlays, makeGlyphPath(glyphPath, gl, lib)) {}

GlyphRenderer::GlyphRenderer(const gl::Api& gl, const gl::ShaderLibrary& lib, OverlayFactories overlays,
                             std::unique_ptr<GlyphPath> path)
    : gl_(gl), lib_(lib), path_(std::move(path)), lighting_(gl, lib) {
  if (!path_) throw std::invalid_argument("GlyphRenderer: no glyph path");
  // The frame's optional passes, in frame order (render/frame_pass.h).
  slots_[kShadow].decl = {"shadow", [](const FrameParams& p) { return p.shadow.enabled; }, makeShadow};
  slots_[kAo].decl = {"ao", [](const FrameParams& p) { return p.ao.enabled; }, make<AoPass>};
  slots_[kAntialias].decl = {"antialias", [](const FrameParams& p) { return p.samples > 1; }, make<AntialiasPass>};
  slots_[kOutline].decl = {"outline", [](const FrameParams& p) { return p.outline.enabled; }, make<OutlinePass>};
  slots_[kOrientation].decl = {"orientation", [](const FrameParams& p) { return p.orientationLetters; },
                               overlays.orientation};
  slots_[kLegend].decl = {"legend", [](const FrameParams& p) { return p.legend.enabled; }, overlays.legend};
}

GlyphRenderer::~GlyphRenderer() {
  if (colorTable_) gl_.DeleteBuffers(1, &colorTable_);
}

void GlyphRenderer::upload(const tensor::GlyphSet& set) {
  path_->upload(set);
  glyphCount_ = set.glyphs.size();
  ranges_.mdMin = float(set.mdMin);
  ranges_.mdMax = float(set.mdMax);
  ranges_.eigenMin = set.eigenvalueMin;
  ranges_.eigenMax = set.eigenvalueMax;
  // MD and the largest |eigenvalue| as the set gives them (a caller may set
  // them field-wide there, as the ParaView plugin does across ranks).
  ranges_.color = render::colorRanges(set);
  ranges_.scalarName.clear();
  hasScalars_ = false;
  if (params_) path_->setColorWindow(colorWindow(*params_));
  typicalDiameter_ = 1.0 / tensor::defaultScale(set, 1.0);
  ++uploads_;
}

void GlyphRenderer::setColorScalars(std::span<const float> byRecord, std::string name) {
  path_->uploadColorScalars(byRecord);
  ranges_.color.of[std::size_t(ColorMode::Array)] = finiteRange(byRecord);
  ranges_.scalarName = std::move(name);
  hasScalars_ = true;
  if (params_) path_->setColorWindow(colorWindow(*params_));
}

void GlyphRenderer::setColorTable(std::span<const glm::vec4> table) {
  if (table.size() < 4)
    throw std::invalid_argument("GlyphRenderer::setColorTable: " + std::to_string(table.size()) +
                                " colours; a table holds at least one, then those of NaN, below and above");
  if (colorTable_) gl_.DeleteBuffers(1, &colorTable_);
  colorTable_ = 0;
  gl_.CreateBuffers(1, &colorTable_);
  gl_.NamedBufferStorage(colorTable_, GLsizeiptr(table.size_bytes()), table.data(), 0);
  gl::checkError(gl_, "GlyphRenderer::setColorTable");
}

void GlyphRenderer::setColorRanges(const ColorRanges& ranges) {
  const glm::dvec2 array = ranges_.color.of[std::size_t(ColorMode::Array)];
  ranges_.color = ranges;
  ranges_.mdMin = float(ranges.of[std::size_t(ColorMode::MD)].x);
  ranges_.mdMax = float(ranges.of[std::size_t(ColorMode::MD)].y);
  if (!(ranges.of[std::size_t(ColorMode::Array)].x <= ranges.of[std::size_t(ColorMode::Array)].y))
    ranges_.color.of[std::size_t(ColorMode::Array)] = array;
  if (params_) path_->setColorWindow(colorWindow(*params_));
}

glm::dvec2 GlyphRenderer::colorWindow(const FrameParams& p) const {
  return resolveColorWindow(p, ranges_.color.of[std::size_t(p.color)], ranges_.color.maxAbsEigenvalue);
}

LegendInputs legendInputs(const FrameParams& p, const UploadedRanges& r) {
  LegendInputs in{p.color, p.scale, r.mdMin, r.mdMax, r.eigenMin, r.eigenMax, p.sizing, r.underlays};
  in.colormap = resolveColormap(p);
  in.window = resolveColorWindow(p, r.color.of[std::size_t(p.color)], r.color.maxAbsEigenvalue);
  in.windowGiven = p.colorWindow.has_value();
  in.scalarName = r.scalarName;
  return in;
}

LegendInputs GlyphRenderer::legendInputs(const FrameParams& p) const {
  UploadedRanges r = ranges_;
  r.underlays = legendKeys();
  return render::legendInputs(p, r);
}

void GlyphRenderer::setParams(const FrameParams& p) {
  const FrameParams* old = params_ ? &*params_ : nullptr;
  if (p.color == ColorMode::Array && !hasScalars_)
    throw std::invalid_argument("GlyphRenderer::render: colour by array, but no per-glyph scalars were set");
  if (p.colorTable && !colorTable_)
    throw std::invalid_argument("GlyphRenderer::render: colour through a table, but no table was set");
  path_->setParams(p, old);
  path_->setColorWindow(colorWindow(p));
  lighting_.setParams(p, old);
  params_ = p;
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

double GlyphRenderer::aoRadiusWC(const FrameParams& p) const {
  return p.ao.radius > 0.0 ? p.ao.radius : AoParams::kAutoRadius * typicalDiameter_ * p.scale;
}

const GlyphRenderer::Slot& GlyphRenderer::slotNamed(std::string_view name) const {
  for (const Slot& s : slots_)
    if (name == s.decl.name) return s;
  throw std::invalid_argument("GlyphRenderer::pass: no pass \"" + std::string(name) + "\"");
}

const FramePass* GlyphRenderer::pass(std::string_view name) const { return slotNamed(name).pass.get(); }
std::uint64_t GlyphRenderer::passRuns(std::string_view name) const { return slotNamed(name).runs; }

int GlyphRenderer::shadowMapSize() const {
  const auto* shadow = static_cast<const ShadowPass*>(slots_[kShadow].pass.get());
  return shadow ? shadow->mapSize() : 0;
}

bool GlyphRenderer::runSlot(Slot& s, const PassFrame& f) {
  if (!s.decl.enabled(f.p)) {
    s.pass.reset();
    return false;
  }
  if (!s.pass) {
    if (!s.decl.make)
      throw std::invalid_argument(std::string("GlyphRenderer::render: this program has no ") + s.decl.name + " pass");
    s.pass = s.decl.make(gl_, lib_);
  }
  s.pass->run(f);
  ++s.runs;
  return true;
}

void GlyphRenderer::render(const Camera& cam, const FrameParams& p, const GBuffer& target,
                           const PassProgress& progress) {
  if (!params_ || !(*params_ == p)) setParams(p);
  gl_.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  // Before the shadow map: its casters run the same vertex stages.
  if (colorTable_) gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_COLOR_TABLE, colorTable_);
  ranges_.underlays = p.legend.enabled ? legendKeys() : std::vector<UnderlayKey>{};
  PassFrame frame{cam, p, target, aoRadiusWC(p), ranges_, *path_, context_, nullptr};
  frame.uploads = uploads_;
  Slot& shadow = slots_[kShadow];
  const bool casts = shadow.decl.enabled(p) && (glyphCount_ > 0 || !context_.empty());
  // The passes this frame runs, for `progress`: the glyphs (with the opaque
  // context) and the lighting (with the translucent context) always.
  int total = 2 + int(casts), done = 0;
  for (const SlotIndex s : {kAo, kAntialias, kOutline, kOrientation, kLegend}) total += int(slots_[s].decl.enabled(p));
  auto finished = [&](std::string_view pass) {
    if (!progress) return;
    gl_.Finish();
    progress(pass, ++done, total);
  };
  auto slot = [&](SlotIndex s) {
    if (runSlot(slots_[s], frame)) finished(slots_[s].decl.name);
  };
  // The shadow map first, so that culling is left prepared for the view; a
  // scene with nothing to cast keeps the pass as it is and draws no map.
  if (!shadow.decl.enabled(p)) shadow.pass.reset();
  else if (casts && runSlot(shadow, frame)) {
    frame.shadow = static_cast<const ShadowPass*>(shadow.pass.get());
    finished("shadow");
  }
  path_->drawView(cam, p, target);
  drawContextOpaque(gl_, context_, cam, p, ContextTarget::View);
  finished("glyphs");
  gl_.Disable(GL_DEPTH_TEST);
  slot(kAo);
  lighting_.run(frame);
  for (const auto& item : context_)
    if (item->visible() && item->translucent()) item->drawTranslucent(cam, p, target);
  finished("lighting");
  // More samples where silhouettes cross pixels. Blobs (and tessellated
  // frames), which no single glyph's cast gives, draw the glyphs, context
  // and lighting again from jittered cameras, with this frame's shadow map
  // and AO; the rest are cast at the samples (render/antialias_pass.h).
  frame.drawSample = [&](const Camera& at, const GBuffer& sample) {
    path_->drawView(at, p, sample);
    drawContextOpaque(gl_, context_, at, p, ContextTarget::View);
    gl_.Disable(GL_DEPTH_TEST);
    lighting_.run(PassFrame{at, p, sample, frame.aoRadiusWC, ranges_, *path_, context_, frame.shadow, {}, true});
    for (const auto& item : context_)
      if (item->visible() && item->translucent()) item->drawTranslucent(at, p, sample);
  };
  slot(kAntialias);
  slot(kOutline);
  slot(kOrientation);
  // Last before readback: the legend draws over every effect.
  slot(kLegend);
  gl::checkError(gl_, "GlyphRenderer::render");
}

std::size_t GlyphRenderer::gpuBytes() const {
  std::size_t bytes = path_->gpuBytes();
  for (const Slot& s : slots_)
    if (s.pass) bytes += s.pass->gpuBytes();
  for (const auto& item : context_) bytes += item->gpuBytes();
  return bytes;
}

FrameImage GlyphRenderer::readback(const Camera& cam, const GBuffer& target, Channels channels) const {
  return readFrame(gl_, cam, target, channels);
}

}  // namespace tg::render
