#include "app/scene.h"

#include "app/scale/cli_values.h"
#include "app/color_array.h"
#include "app/field_flags.h"

#include "data-synthetic/generators.h"
#include "io/core/readers.h"
#include "io/core/selection.h"

#include <algorithm>
#include <cmath>
#include <span>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace tg::app {

Scene defaultScene() {
  Scene s;
  s.field = synth::helixPhantom(40, 40, 20).field;
  s.field.path = "(built-in helix phantom)";
  render::CameraDesc cam;
  // Frame the field's bounding sphere from an oblique direction (30 deg fov).
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (std::size_t i = 0; i < s.field.size(); ++i) {
    const glm::dvec3 p(s.field.positions[3 * i], s.field.positions[3 * i + 1], s.field.positions[3 * i + 2]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double r = 0.5 * glm::length(hi - lo);
  cam.lookAtWC = 0.5 * (lo + hi);
  cam.eyeWC = cam.lookAtWC + glm::normalize(glm::dvec3(0.9, -1.6, 1.25)) * (0.42 * r / std::sin(glm::radians(15.0)));  // the helix fills ~half the box
  cam.upWC = glm::dvec3(0, 0, 1);
  cam.fovYDeg = 30.0;
  s.preferredCamera = cam;
  s.preferredFaMin = 0.25;
  s.preferredLook = SceneLook{};
  return s;
}

Scene loadScene(const std::string& input, const io::ReadOptions& opt) {
  checkOptionsApply(input, opt);
  Scene s;
  try {
    if (input.empty()) {
      s = defaultScene();
      io::applySelection(s.field, opt.selection);
    } else {
      s.field = io::readTensorField(input, opt);
    }
  } catch (const io::SliceOutOfRange& e) {
    throw sliceUsageError(e, *opt.selection.slice, input);
  }
  checkLoaded(s.field, opt);
  return s;
}

namespace {

// The options of the load that left tensors of `f` out, " --slice --mask": "" when none did.
std::string loadLeftOutBy(const io::TensorField& f, const io::Selection& sel) {
  std::string by = std::string(sel.slice ? " --slice" : "") + (sel.stride > 1 ? " --stride" : "") +
                   (sel.roiWC ? " --roi" : "");
  if (!sel.maskPath.empty() && f.masked > 0) by += " --mask";
  return by;
}

}  // namespace

void attachWholeField(Scene& s, const FieldFlags& flags, const std::function<io::TensorField()>& whole) {
  s.wholeField.reset();
  const std::string byLoad = loadLeftOutBy(s.field, flags.read.selection);
  const std::string by = byLoad + (flags.glyph.clMin > 0 ? " --cl-min" : "") + (flags.glyph.cpMin > 0 ? " --cp-min" : "");
  if (by.empty()) {
    s.sizesFrom = "the whole field (" + std::to_string(s.field.size()) + " tensors)";
    return;
  }
  if (flags.sizesFromSelection) {
    s.sizesFrom = "the selection (" + by.substr(1) + "; --sizes-from selection)";
    return;
  }
  // A shape filter alone leaves every tensor loaded: no second read.
  const io::TensorField read = byLoad.empty() ? io::TensorField{} : whole();
  const io::TensorField& f = byLoad.empty() ? s.field : read;
  // The shape filters are a selection too: every tensor counts.
  tensor::GlyphOptions g = flags.glyph;
  g.clMin = g.cpMin = 0;
  const tensor::GlyphSet set = tensor::buildGlyphs(f.positions, f.tensors, f.ids, 0, g);
  // The magnitudes are the whole field's; the spacing stays that of the
  // samples drawn, which depends on the grid, the stride and the slice's
  // axis but not on which slice: a thinned slice's glyphs grow to the
  // thinned spacing (io::Selector::keptSpacing).
  WholeField w{tensor::fieldStats(set), s.field.sampleSpacing, render::colorRanges(set)};
  if (const auto values = colorArrayValues(flags.read.colorArray, f, set, s.colorVolume))
    w.colors.of[std::size_t(render::ColorMode::Array)] =
        render::finiteRange(std::span(values->byRecord.data(), values->byRecord.size()));
  s.wholeField = std::move(w);
  s.sizesFrom = "the whole field (" + std::to_string(set.glyphs.size()) + " tensors, before" + by +
                "; --sizes-from selection for the selection's own)";
}

void attachWholeField(Scene& s, const FieldFlags& flags, const std::string& input, io::ReadOptions read) {
  attachWholeField(s, flags, [&] {
    read.selection.slice.reset();
    read.selection.stride = 1;
    read.selection.roiWC.reset();
    read.selection.maskPath.clear();
    if (input.empty()) return defaultScene().field;
    return io::readTensorField(input, read);
  });
}

void decideStressDefaults(Scene& s, const tensor::FieldStats& stats) {
  if (s.preferredLook) return;
  s.stress = stressDefaults(s.field, stats);
  if (s.stress) s.preferredLook = stressLook();
}

tensor::ScaleParams sizingParams(const FieldFlags& flags, const Scene& s) {
  tensor::ScaleParams p = flags.scaleParams();
  if (s.stress && !flags.magnitudeGiven) p.magnitude = kStressMagnitude;
  return p;
}

tensor::FieldStats sizingStats(const Scene& s, const tensor::GlyphSet& glyphs) {
  return s.wholeField ? s.wholeField->stats : tensor::fieldStats(glyphs);
}

tensor::MagnitudeSample sizingSample(const Scene& s, const tensor::FieldStats& stats) {
  return tensor::magnitudeSample(stats, s.wholeField ? s.wholeField->sampleSpacing : s.field.sampleSpacing, s.sizesFrom);
}

UsageError sliceUsageError(const io::SliceOutOfRange& e, const io::SliceSpec& asked, const std::string& input) {
  const std::string grid = " of the grid of " + (input.empty() ? std::string("the built-in scene") : input);
  const std::string range = "0.." + std::to_string(e.size - 1);
  const char axis = "xyz"[e.spec.axis];
  if (asked.positionWC)
    return UsageError("--slice " + asked.text() + ": the position falls at index " + std::to_string(e.spec.index) +
                      " along voxel axis " + "ijk"[e.spec.axis] + ", outside " + range + grid);
  if (asked.worldAxis >= 0)
    return UsageError("--slice " + asked.text() + ": index " + std::to_string(e.spec.index) + " is outside " + range +
                      " along voxel axis " + "ijk"[e.spec.axis] + " (the nearest " + "RAS"[asked.worldAxis] + ")" + grid);
  return UsageError("--slice " + asked.text() + ": index " + std::to_string(e.spec.index) + " is outside " + range +
                    " along " + axis + grid);
}

render::CameraDesc sceneCamera(const Scene& s, const glm::dvec3& loWC, const glm::dvec3& hiWC, render::Projection p,
                               double fovYDeg, double aspect) {
  render::CameraDesc d = render::fitBox(loWC, hiWC, p, fovYDeg, aspect);
  if (s.preferredCamera) {
    d.eyeWC = s.preferredCamera->eyeWC;
    d.lookAtWC = s.preferredCamera->lookAtWC;
    d.upWC = s.preferredCamera->upWC;
  }
  return d;
}

void growDepthRange(glm::dvec3& lo, glm::dvec3& hi, const glm::dvec3& itemLo, const glm::dvec3& itemHi) {
  if (!(itemLo.x <= itemHi.x && itemLo.y <= itemHi.y && itemLo.z <= itemHi.z)) return;  // empty
  const double reach = kContextReach * std::max(glm::length(hi - lo), 1e-30);
  lo = glm::min(lo, glm::max(itemLo, lo - reach));
  hi = glm::max(hi, glm::min(itemHi, hi + reach));
}

}  // namespace tg::app
