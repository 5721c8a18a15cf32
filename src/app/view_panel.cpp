#define GLFW_INCLUDE_NONE
#include "app/view_panel.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "app/scale/option_ranges.h"
#include "render/color_scalar.h"

namespace tg::app {
namespace {

// A slider over the range the option declares (app/scale/option_ranges.h).
bool slider(const char* label, float* v, const NumberRange& r, const char* format = "%.3g", bool logarithmic = false) {
  return ImGui::SliderFloat(label, v, float(r.lo), float(r.hi), format,
                            logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
}

// Magnitude mapping and clamp: resolved again from the kept magnitudes, so
// a change is uniforms only (resize()).
void sizeControls(ViewState& v) {
  int mapping = int(v.sizing.magnitude);
  bool changed = false;
  if (ImGui::Combo("magnitude", &mapping, "linear\0log\0shape only\0")) {
    v.sizing.magnitude = tensor::Magnitude(mapping);
    changed = true;
  }
  bool clamped = v.params.sizing.maxRadiusWC > 0.0;
  if (ImGui::Checkbox("clamp", &clamped)) {
    v.sizing.clampSpacings = clamped ? tensor::ScaleParams::kDefaultClamp : 0.0;
    changed = true;
  }
  if (clamped) {
    ImGui::SameLine();
    auto n = float(v.sizing.clampSpacings.value_or(tensor::ScaleParams::kDefaultClamp));
    if (ImGui::SliderFloat("spacings", &n, 0.25f, 20.0f, "%.2f", ImGuiSliderFlags_Logarithmic)) {
      v.sizing.clampSpacings = n;
      changed = true;
    }
  }
  if (changed) resize(v);
}

void depthCues(render::FrameParams& p, const PanelStatus& s) {
  if (!ImGui::CollapsingHeader("depth cues")) return;
  ImGui::Checkbox("ambient occlusion", &p.ao.enabled);
  if (p.ao.enabled) {
    // Starts from the radius in use (auto until moved), in world units.
    auto radius = float(s.aoRadiusWC);
    if (ImGui::DragFloat("AO radius", &radius, 0.01f * radius, 0.0f, 1e30f, "%.4g", ImGuiSliderFlags_Logarithmic) &&
        radius > 0.0f)
      p.ao.radius = radius;
    auto strength = float(p.ao.strength);
    if (slider("AO strength", &strength, ranges::kAoStrength, "%.2f"))
      p.ao.strength = strength;
    ImGui::SliderInt("AO samples", &p.ao.samples, int(ranges::kAoSamples.lo), int(ranges::kAoSamples.hi));
  }
  ImGui::Checkbox("outlines", &p.outline.enabled);
  if (p.outline.enabled) {
    auto width = float(p.outline.width);
    if (slider("line width", &width, ranges::kOutlineWidth, "%.2f px"))
      p.outline.width = width;
    auto crease = float(p.outline.creaseDeg);
    if (slider("crease angle", &crease, ranges::kCreaseDeg, "%.0f deg")) p.outline.creaseDeg = crease;
    ImGui::ColorEdit4("line colour", &p.outline.color[0]);
  }
}

// On a grid, the slab in --slice's terms: an anatomical plane (on the voxel
// axis nearest it, as --slice axial:N picks), its index and thickness. A
// point set has no grid: a world range across x, y or z.
void slabControls(ViewState& v, const tensor::GlyphSet& meta) {
  render::FrameParams& p = v.params;
  if (v.fieldGrid) {
    const SliceGrid& g = *v.fieldGrid;
    // 0 off; 1, 2, 3: axial, coronal, sagittal (world axes z, y, x); 4, 5, 6: voxel axes i, j, k.
    const std::optional<io::SliceSpec>& now = v.slabSlice;
    int plane = !now ? 0 : now->worldAxis >= 0 ? 3 - now->worldAxis : 4 + now->axis;
    io::SliceSpec s = v.slabSlice.value_or(io::SliceSpec{});
    bool changed = false;
    if (ImGui::Combo("slab", &plane, "off\0axial\0coronal\0sagittal\0voxel i\0voxel j\0voxel k\0")) {
      changed = true;
      if (plane > 0) {
        s = io::SliceSpec{plane >= 4 ? plane - 4 : 2};
        if (plane < 4) s.worldAxis = 3 - plane;
        s = io::resolveSlice(s, g.placement, g.dims);
        s.index = g.dims[s.axis] / 2;  // start at the middle, one voxel thick
      }
    }
    if (plane > 0) {
      const int n = g.dims[s.axis];
      int index = int(s.index), thick = int(s.thickness);
      const std::string axisName = std::string("voxel ") + "ijk"[s.axis];
      if (ImGui::SliderInt("slab index", &index, 0, n - 1, (axisName + " %d").c_str())) changed = true;
      if (ImGui::SliderInt("slab thickness", &thick, 1, n)) changed = true;
      s.index = std::clamp(index, 0, n - 1);
      s.thickness = std::clamp(thick, 1, n);
      s.positionWC.reset();  // now an index, as the script's `slab axial:N`
    }
    if (changed) {
      v.slabSlice = plane > 0 ? std::optional(s) : std::nullopt;
      p.slab = plane > 0 ? slabOf(s, g) : render::Slab{};
    }
    return;
  }
  int axis = p.slab.axis + 1;
  if (ImGui::Combo("slab (world)", &axis, "off\0x\0y\0z\0")) {
    p.slab.axis = axis - 1;
    p.slab.normalWC = glm::dvec3(0.0);
    if (p.slab.axis >= 0) {
      // Start as one sample thick, at the middle of the centres' range.
      const double lo = meta.boundsMinWC[p.slab.axis], hi = meta.boundsMaxWC[p.slab.axis];
      const double mid = 0.5 * (lo + hi), half = std::max(0.5, 0.01 * (hi - lo));
      p.slab.lo = mid - half;
      p.slab.hi = mid + half;
    }
  }
  if (p.slab.axis >= 0) {
    const auto lo = float(meta.boundsMinWC[p.slab.axis]), hi = float(meta.boundsMaxWC[p.slab.axis]);
    float range[2] = {float(p.slab.lo), float(p.slab.hi)};
    if (ImGui::DragFloat2("slab range", range, std::max(1e-3f, 0.002f * (hi - lo)), lo, hi)) {
      p.slab.lo = std::min(range[0], range[1]);
      p.slab.hi = std::max(range[0], range[1]);
    }
  }
}

void controls(ViewState& v, const tensor::GlyphSet& meta, const PanelStatus& status) {
  render::FrameParams& p = v.params;
  int kind = int(p.glyph);
  // The kind table's names (literals, so NUL-terminated).
  auto kindName = [](void*, int k, const char** out) {
    *out = render::glyphKinds()[std::size_t(k)].name.data();
    return true;
  };
  if (ImGui::Combo("glyph", &kind, kindName, nullptr, int(render::glyphKinds().size()))) {
    if (render::pathDraws(status.glyphPath, render::GlyphKind(kind))) p.glyph = render::GlyphKind(kind);
  }
  if (!render::pathDraws(status.glyphPath, render::GlyphKind::Blob))
    ImGui::TextDisabled("blob: start the viewer with --glyph blob (the cpu path)");
  auto gamma = float(p.gamma);
  if (slider("gamma", &gamma, ranges::kGamma, "%.2f", true)) p.gamma = gamma;
  if (p.glyph == render::GlyphKind::Blob) {
    auto threshold = float(p.blob.threshold), blobbiness = float(p.blob.blobbiness);
    // Of the options' ranges, the part where a picture changes.
    if (ImGui::SliderFloat("blob threshold", &threshold, 0.05f, 20.0f, "%.3g", ImGuiSliderFlags_Logarithmic))
      p.blob.threshold = threshold;
    if (ImGui::SliderFloat("blobbiness", &blobbiness, -20.0f, -0.05f, "%.3g")) p.blob.blobbiness = blobbiness;
  }
  auto fa = float(p.faMin);
  if (slider("FA min", &fa, ranges::kUnit, "%.3f")) p.faMin = fa;
  auto factor = float(v.scaleFactor);
  if (ImGui::SliderFloat("scale", &factor, 0.05f, 20.0f, "x %.2f", ImGuiSliderFlags_Logarithmic)) {
    v.scaleFactor = factor;
    p.scale = v.baseScale * factor;
  }
  sizeControls(v);
  // In render::ColorMode's order; the array only where a script chose it.
  int color = int(p.color);
  const char* const colorNames[render::kColorModeCount] = {
      "DEC (principal direction)", "FA", "mean diffusivity", "cl", "cp", "sign (normal stress)", "von Mises",
      "Tresca", "pressure", "s1", "s2", "s3", "trace", "DEC x FA", "array"};
  if (ImGui::Combo("colour", &color, colorNames, render::kColorModeCount - (p.color == render::ColorMode::Array ? 0 : 1)))
    p.color = render::ColorMode(color);
  if (render::colorIsScalar(p.color)) {
    int map = int(render::resolveColormap(p));
    if (ImGui::Combo("colormap", &map, "gray\0viridis\0diverging\0")) p.colormap = render::Colormap(map);
  }

  slabControls(v, meta);
  if (ImGui::CollapsingHeader("legend")) {
    ImGui::Checkbox("show legend", &p.legend.enabled);
    int corner = int(p.legend.corner);
    if (ImGui::Combo("corner", &corner, "top left\0top right\0bottom left\0bottom right\0"))
      p.legend.corner = render::LegendCorner(corner);
    ImGui::Checkbox("colour key", &p.legend.colorKey);
    ImGui::SameLine();
    ImGui::Checkbox("scale bar", &p.legend.scaleBar);
  }
  if (ImGui::CollapsingHeader("lighting")) {
    slider("ambient", &p.light.ambient, ranges::kLight);
    slider("headlight", &p.light.head, ranges::kLight);
    slider("key light", &p.light.key, ranges::kLight);
    slider("specular", &p.light.specular, ranges::kLight);
    slider("shininess", &p.light.shininess, ranges::kShininess, "%.0f", true);
  }
  ImGui::Checkbox("shadows", &p.shadow.enabled);
  if (p.shadow.enabled && ImGui::CollapsingHeader("shadow parameters")) {
    slider("penumbra", &p.shadow.penumbra, ranges::kShadowPenumbra, "%.4f", true);
    slider("shadow strength", &p.shadow.strength, ranges::kUnit);
    slider("shadow bias", &p.shadow.bias, ranges::kShadowBias, "%.2f texels", true);
    // 0: follow the view (ShadowParams::mapDensity); then fixed sizes; 5: another, from a script.
    const int sizes[5] = {0, 512, 1024, 2048, 4096};
    int k = p.shadow.mapDensity > 0.0f ? 0 : int(std::find(sizes + 1, sizes + 5, p.shadow.mapSize) - sizes);
    if (ImGui::Combo("shadow map", &k, "follow the view\0" "512\0" "1024\0" "2048\0" "4096\0") && k < 5) {
      const render::ShadowParams d;
      p.shadow.mapDensity = k == 0 ? d.mapDensity : 0.0f;
      p.shadow.mapSize = k == 0 ? d.mapSize : sizes[k];
    }
  }
  if (!v.meshes.empty() && ImGui::CollapsingHeader("meshes", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (std::size_t k = 0; k < v.meshes.size(); ++k) {
      MeshView& m = v.meshes[k];
      ImGui::PushID(int(k));
      ImGui::Checkbox(m.label.c_str(), &m.visible);
      int mode = int(m.params.mode);
      if (ImGui::Combo("drawn", &mode, "opaque\0see-through\0edges\0")) m.params.mode = render::MeshMode(mode);
      if (m.params.mode == render::MeshMode::SeeThrough) slider("opacity", &m.params.opacity, ranges::kUnit);
      if (m.params.mode == render::MeshMode::Edges)
        slider("feature angle", &m.params.featureAngleDeg, ranges::kFeatureAngleDeg, "%.0f deg");
      ImGui::PopID();
    }
  }
  if (!v.tracts.empty() && ImGui::CollapsingHeader("tracts", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (std::size_t k = 0; k < v.tracts.size(); ++k) {
      TractView& t = v.tracts[k];
      ImGui::PushID(int(k));
      ImGui::Checkbox(t.label.c_str(), &t.visible);
      ImGui::Checkbox("coloured by direction", &t.params.byDirection);
      if (!t.params.byDirection) ImGui::ColorEdit3("colour", &t.params.color[0]);
      // Tube diameter in world units, from a hundredth to 100 times the start.
      float width = t.params.widthWC;
      if (ImGui::DragFloat("tube width", &width, 0.01f * width, float(ranges::kTractWidth.lo), float(ranges::kTractWidth.hi),
                           "%.3g", ImGuiSliderFlags_Logarithmic) && width > 0.0f)
        t.params.widthWC = width;
      ImGui::PopID();
    }
  }
  if (ImGui::CollapsingHeader("superquadric march")) {
    ImGui::SliderInt("iterations", &p.march.maxIterations, int(ranges::kIterations.lo), int(ranges::kIterations.hi), "%d",
                     ImGuiSliderFlags_Logarithmic);
    auto eps = float(p.march.epsilon);
    if (slider("epsilon", &eps, ranges::kEpsilon, "%.1e", true)) p.march.epsilon = eps;
    ImGui::Checkbox("Newton statistics", &p.iterationStats);
  }
}

// Each plane on or off, and an index plane's slice: the viewer moves its quad
// (no upload). Numbered as the script's `plane N`.
void slicePlanes(ViewState& v) {
  if (v.planes.empty() || !ImGui::CollapsingHeader("slice planes", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (std::size_t k = 0; k < v.planes.size(); ++k) {
    PlaneView& plane = v.planes[k];
    ImGui::PushID(int(k));
    // "###": one widget id while the label follows the index.
    ImGui::Checkbox((std::to_string(k + 1) + ": " + plane.spec.label() + "###visible").c_str(), &plane.visible);
    if (plane.slices > 1) {
      int index = int(plane.spec.index);
      if (ImGui::SliderInt("index", &index, 0, int(plane.slices - 1)))
        plane.spec.index = std::clamp<long long>(index, 0, plane.slices - 1);
    }
    ImGui::PopID();
  }
}

// Mouse and keys reach the view only when the panel does not want them.
void navigate(ViewState& v, PanelActions& act) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureMouse) {
    const float height = std::max(1.0f, io.DisplaySize.y);
    const bool panning = io.MouseDown[1] || io.MouseDown[2] || (io.MouseDown[0] && io.KeyShift);
    if (panning) v.camera.pan(io.MouseDelta.x / height, -io.MouseDelta.y / height);
    else if (io.MouseDown[0]) v.camera.orbit(0.3 * io.MouseDelta.x, 0.3 * io.MouseDelta.y);
    if (io.MouseWheel != 0.0f) v.camera.zoom(std::pow(1.1, double(io.MouseWheel)));
  }
  // A left click that did not drag (an orbit of nothing) picks; one that
  // began on the panel belongs to the panel.
  const float slop = io.MouseDragThreshold;
  if (io.MouseReleased[0] && !io.MouseDownOwned[0] && !io.KeyShift && io.MouseDragMaxDistanceSqr[0] < slop * slop) {
    const int i = int(std::floor(io.MousePos.x * io.DisplayFramebufferScale.x));
    const int j = int(std::floor(io.MousePos.y * io.DisplayFramebufferScale.y));
    if (i >= 0 && j >= 0) act.pick = PixelIJ{i, j};
  }
  if (!io.WantCaptureKeyboard) {
    if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) v.camera.reset();
    if (ImGui::IsKeyPressed(GLFW_KEY_1, false)) turnToView(v, "axial");
    if (ImGui::IsKeyPressed(GLFW_KEY_2, false)) turnToView(v, "coronal");
    if (ImGui::IsKeyPressed(GLFW_KEY_3, false)) turnToView(v, "sagittal");
    if (ImGui::IsKeyPressed(GLFW_KEY_V, false)) {
      v.radiological = !v.radiological;
      if (v.view == "axial" || v.view == "coronal") turnToView(v, v.view);
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_L, false)) v.params.orientationLetters = !v.params.orientationLetters;
    if (ImGui::IsKeyPressed(GLFW_KEY_S, false)) act.screenshot = true;
    if (ImGui::IsKeyPressed(GLFW_KEY_Q, false) || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) act.quit = true;
  }
}

}  // namespace

PanelActions drawPanel(ViewState& v, const PanelStatus& s, const tensor::GlyphSet& meta) {
  PanelActions act;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("tensorglyph");
  controls(v, meta, s);
  depthCues(v.params, s);
  slicePlanes(v);
  if (ImGui::Button("axial (1)")) turnToView(v, "axial");
  ImGui::SameLine();
  if (ImGui::Button("coronal (2)")) turnToView(v, "coronal");
  ImGui::SameLine();
  if (ImGui::Button("sagittal (3)")) turnToView(v, "sagittal");
  if (bool r = v.radiological; ImGui::Checkbox("radiological (V)", &r)) {
    v.radiological = r;
    if (v.view == "axial" || v.view == "coronal") turnToView(v, v.view);
  }
  ImGui::SameLine();
  ImGui::Checkbox("letters (L)", &v.params.orientationLetters);
  if (ImGui::Button("reset view (R)")) v.camera.reset();
  ImGui::SameLine();
  if (ImGui::Button("screenshot (S)")) act.screenshot = true;
  ImGui::Separator();
  ImGui::Text("%.1f fps | %llu of %llu glyphs drawn", s.fps, static_cast<unsigned long long>(s.drawn),
              static_cast<unsigned long long>(s.total));
  if (v.params.iterationStats)
    ImGui::Text("Newton: mean %.2f, max %u over %llu pixels", s.newton.mean, s.newton.max,
                static_cast<unsigned long long>(s.newton.pixels));
  ImGui::Text("last change: %.1f us CPU", s.lastChangeUs);
  if (ImGui::CollapsingHeader("picked (click a glyph)", ImGuiTreeNodeFlags_DefaultOpen))
    ImGui::TextUnformatted(s.picked ? s.picked->c_str() : "nothing yet");
  ImGui::End();
  navigate(v, act);
  return act;
}

}  // namespace tg::app
