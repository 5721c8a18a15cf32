// tensorglyph view: a GLFW window with a Dear ImGui panel over the same
// scene and renderer as `render` (app/render_session.h). Every control is a
// uniform (GlyphRenderer::setParams); nothing is re-uploaded or recomputed on
// the CPU after the first frame.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "app/scale/option_table.h"
#include "app/render_options.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/scene_flags.h"
#include "app/field_flags.h"
#include "app/scale/frame_size.h"
#include "app/effect_flags.h"
#include "app/legend_flags.h"
#include "app/look_flags.h"
#include "app/shadow_flags.h"
#include "app/slice_flags.h"
#include "app/names.h"
#include "app/output_check.h"
#include "app/pick.h"
#include "app/pick_json.h"
#include "app/render_session.h"
#include "app/scene.h"
#include "app/view_panel.h"
#include "app/view_script.h"
#include "app/mesh_flags.h"
#include "gl/backends/glfw/context_glfw.h"
#include "io/core/image_writer.h"
#include "render/slice_plane.h"

namespace tg::app {
namespace {

// `render`'s options where a window has use for them (render_options.h), and
// the viewer's own.
// The window's size is render's default image size.
struct ViewOptions : RenderOptions {
  std::string script, shotPrefix = "tensorglyph-view-";
};

ViewOptions parse(int argc, const char** argv) {
  ViewOptions o;
  OptionTable ap("tensorglyph view [INPUT] [options]\n"
           "  mouse: left drag orbits, right or middle drag pans, wheel zooms\n"
           "  keys: R resets the view, 1 2 3 turn to axial, coronal, sagittal, V swaps radiological and\n"
           "  neurological, L shows or hides the orientation letters, S saves a screenshot, Q or Esc quits");
  using Args = OptionArgs;
  addViewOptions(ap, o);
  ap.arg("--script FILE").help("run the commands in FILE (see docs/guide.md, \"Viewer\"), then exit")
      .action([&](Args a) { o.script = a[1]; });
  ap.arg("--screenshot-prefix P").help("key S saves P0000.png, P0001.png, ... (default tensorglyph-view-)")
      .action([&](Args a) { o.shotPrefix = a[1]; });
  parseCommandLine(ap, argc, argv);
  return o;
}

void validate(const ViewOptions& o) {
  validateRenderOptions(o, false);
  // Smaller windows leave no room for the panel.
  if (o.width < 64 || o.height < 64) throw UsageError("--size: a window is at least 64 x 64");
}

// The median of a sample, 0 for none.
double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

void saveScreenshot(render::GlyphRenderer& r, const render::Camera& cam, const render::GBuffer& t,
                    const std::string& path) {
  // Screenshots are PNG: the 8-bit colour alone, read back in bands as render's.
  io::writeImage(r.readback(cam, t, render::Channels::Rgba8), path);
  std::fprintf(stderr, "tensorglyph view: saved %s\n", printable(path).c_str());
}

}  // namespace

int cmdView(int argc, const char** argv) {
  const ViewOptions o = parse(argc, argv);
  validate(o);
  // The script is checked whole before anything is loaded or opened.
  const std::vector<ScriptStep> script = o.script.empty() ? std::vector<ScriptStep>{} : parseScript(o.script);
  std::vector<NamedPath> scriptShots;
  for (const ScriptStep& s : script)
    if (s.verb == "screenshot") scriptShots.push_back({o.script + ":" + std::to_string(s.line) + ": screenshot", s.args[0]});
  for (const ScriptStep& s : script)
    if (s.verb == "pick" && (s.integer(0) >= o.width || s.integer(1) >= o.height))
      throw io::InputError(o.script + ":" + std::to_string(s.line) + ": pick: the pixel is outside the " +
                           std::to_string(o.width) + " x " + std::to_string(o.height) + " window");
  std::vector<NamedPath> inputs = sceneInputs(o.input, o);
  inputs.push_back({"--script", o.script});
  refuseOutputsOverInputs(scriptShots, inputs);
  Scene scene = loadScene(o.input, o.field.read);
  attachWholeField(scene, o.field, o.input, o.field.read);
  reportLoad(scene.field, "view", o.field.read);
  std::vector<io::MeshData> meshes = o.mesh.read(o.input, "view");
  checkScriptMeshes(script, meshes.size(), o.script);
  const std::string path = sessionGlyphPath(o);
  // A viewer on a path that draws no blobs never shows them: their options would do nothing.
  if (!o.blobFlag.empty() && !pipelineDraws(path, render::GlyphKind::Blob))
    throw UsageError(o.blobFlag + " applies to --glyph blob only, and this viewer draws on the " + path +
                     " glyph path, which draws none; start it with --glyph blob");
  for (const ScriptStep& s : script)
    if (s.verb == "glyph" && !pipelineDraws(path, *glyphKindNamed(s.args[0])))
      throw UsageError(o.script + ":" + std::to_string(s.line) + ": glyph " + s.args[0] + ": the viewer draws on the " +
                       path + " glyph path, which draws no " + s.args[0] + " glyphs; start it with --glyph " + s.args[0]);
  const std::size_t meshCount = meshes.size();
  // The scene as `render` builds it (app/render_session.h): glyphs, underlay
  // and its warnings, meshes; only the window, its events and the panel are
  // the viewer's. Clicks pick at any time: the samples stay (app/pick.h), 40
  // bytes a tensor, taken after the field's own scalar underlay read them.
  std::optional<PickTable> pickTable;
  ViewState v{render::FrameParams{}, OrbitCamera(render::CameraDesc{}), 1.0, 1.0, o.field.scaleParams(), {}};
  if (scene.field.grid) v.fieldGrid = sliceGridOf(*scene.field.grid);
  checkSlabSteps(script, v.fieldGrid, o.script);
  SessionHooks hooks;
  // --pipeline auto takes a path that draws whatever the script switches to.
  for (const ScriptStep& s : script)
    if (s.verb == "glyph") hooks.alsoDraws.push_back(*glyphKindNamed(s.args[0]));
  if (!o.blobFlag.empty()) hooks.alsoDraws.push_back(render::GlyphKind::Blob);
  hooks.underlayLoaded = [&](const render::UnderlayVolume& underlay) {
    for (const render::PlaneSpec& spec : o.slices.planesFor(underlay))
      v.planes.push_back({spec, true, spec.axis >= 0 ? underlay.dims[spec.axis] : 0});
    v.underlayGrid = sliceGridOf(underlay);
  };
  hooks.makeContext = [&](const RenderOptions&) {
    // The script's plane steps are checked before the window opens.
    checkPlaneSteps(script, v.planes, o.script, v.underlayGrid);
    try {
      return gl::createGlfwContext({o.width, o.height, true, "tensorglyph"});
    } catch (const std::runtime_error& e) {
      // Most often no display at all: a server, a container, CI.
      throw std::runtime_error(std::string(e.what()) +
                               "; without a display use `xvfb-run -a tensorglyph view ...`, or `tensorglyph render` "
                               "for headless images");
    }
  };
  RenderSession session(o, std::move(scene), std::move(meshes), false, "view", [&](io::TensorField& f) {
    pickTable.emplace(f, o.field.glyph);
    f.releaseSamples();
  }, {}, hooks);
  const tensor::GlyphSet& glyphs = session.glyphs();  // counts and box: the records are dropped
  v.magnitudes = session.magnitudes();
  v.sizing = sizingParams(o.field, session.scene());  // a stress field's defaults are known now
  // As render frames it: the sample positions (tensor::framingBox) or the
  // camera the flags give, with room for a legend shown from the start.
  const RenderSession::Frame first = session.frame(o);
  v.params = first.params;
  resize(v);
  render::FrameParams& p = v.params;
  v.camera = OrbitCamera(first.camera.desc);
  v.radiological = o.radiological.value_or(false);
  // The view it starts in, which the convention key turns again.
  v.view = !o.view.empty() || o.eye || o.field.read.selection.slice || session.scene().preferredCamera ? o.view : "axial";

  GLFWwindow* window = gl::glfwWindowOf(session.context());
  glfwSwapInterval(script.empty() ? 1 : 0);  // a script runs as fast as it can
  const gl::Api& api = session.context().api();
  render::GlyphRenderer& renderer = session.renderer();
  // Moving or hiding a plane later changes its quad only: the volume stays on the GPU.
  const std::span<render::SlicePlane* const> planes = session.slicePlanes();
  std::vector<PlaneView> appliedPlanes = v.planes;
  // Context items in the order added: the planes, the tracts, then the meshes.
  std::vector<render::TractItem*> tractItems;
  for (const auto& item : renderer.context())
    if (auto* t = dynamic_cast<render::TractItem*>(item.get())) {
      tractItems.push_back(t);
      v.tracts.push_back({t->label(), true, t->params()});
    }
  std::vector<render::MeshItem*> meshItems;
  for (std::size_t k = renderer.context().size() - meshCount; k < renderer.context().size(); ++k) {
    const auto& item = renderer.context()[k];
    meshItems.push_back(static_cast<render::MeshItem*>(item.get()));
    v.meshes.push_back({item->label(), true, o.mesh.params});
  }
  const std::size_t glyphCount = session.glyphCount();

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's directory
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450");

  std::optional<render::FrameParams> applied;
  std::vector<double> changeUs, frameMs;
  PanelStatus status;
  status.glyphPath = std::string(renderer.glyphPath().name());
  std::size_t step = 0;
  int framesLeft = 0, shots = 0;
  std::optional<Clock::time_point> lastFrame;
  while (!glfwWindowShouldClose(window)) {
    // The frame period, swap to swap: what the user sees, with the GPU's work in it.
    if (lastFrame) frameMs.push_back(msSince(*lastFrame));
    lastFrame = Clock::now();
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    std::optional<std::string> shot;
    std::optional<PixelIJ> scriptPick;
    if (!o.script.empty()) {
      if (framesLeft > 0) {
        --framesLeft;
      } else if (step < script.size()) {
        const ScriptStep& s = script[step++];
        if (s.verb == "screenshot") shot = s.args[0];
        else if (s.verb == "pick")
          scriptPick = PixelIJ{s.integer(0), s.integer(1)};
        else if (s.verb == "frames") framesLeft = s.integer(0) - 1;
        else applyStep(s, v);
      } else {
        glfwSetWindowShouldClose(window, GLFW_TRUE);
      }
    }
    const PanelActions act = drawPanel(v, status, glyphs);
    if (act.quit) glfwSetWindowShouldClose(window, GLFW_TRUE);
    if (act.screenshot) shot = o.shotPrefix + std::to_string(10000 + shots++).substr(1) + ".png";

    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    if (w > 0 && h > 0) {
      const render::GBuffer& target = session.target(w, h);
      if (!applied || !(*applied == p)) {
        // The whole CPU cost of a parameter change: uniform updates.
        const auto t = Clock::now();
        renderer.setParams(p);
        const double us = 1000.0 * msSince(t);
        if (applied) changeUs.push_back(us);
        status.lastChangeUs = us;
        applied = p;
      }
      for (std::size_t k = 0; k < planes.size(); ++k) {
        if (v.planes[k] == appliedPlanes[k]) continue;
        const auto t = Clock::now();
        planes[k]->setVisible(v.planes[k].visible);
        planes[k]->setSpec(v.planes[k].spec);
        const double us = 1000.0 * msSince(t);
        changeUs.push_back(us);
        status.lastChangeUs = us;
        appliedPlanes[k] = v.planes[k];
      }
      // The camera's depth range holds the planes and meshes too, as render's.
      const auto [lo, hi] = session.depthBoxWC(p);
      for (std::size_t k = 0; k < meshItems.size(); ++k) {
        meshItems[k]->setVisible(v.meshes[k].visible);
        if (!(meshItems[k]->params() == v.meshes[k].params)) meshItems[k]->setParams(v.meshes[k].params);
      }
      for (std::size_t k = 0; k < tractItems.size(); ++k) {  // uniforms only: the tubes stay uploaded
        tractItems[k]->setVisible(v.tracts[k].visible);
        tractItems[k]->setParams(v.tracts[k].params);
      }
      const render::Camera cam = render::makeCamera(v.camera.desc(), w, h, lo, hi);
      renderer.render(cam, p, target);
      // Never waits for the GPU: the status trails the frame by one or two.
      renderer.requestDrawnCount();
      status.drawn = renderer.latestDrawnCount().value_or(status.drawn);
      status.total = glyphCount;
      if (p.iterationStats) status.newton = renderer.iterationStats();
      status.aoRadiusWC = renderer.aoRadiusWC(p);
      status.fps = ImGui::GetIO().Framerate;
      if (shot) saveScreenshot(renderer, cam, target, *shot);
      if (act.pick && act.pick->i < w && act.pick->j < h)
        status.picked = describePick(pickPixel(api, renderer, cam, target, *pickTable, *act.pick));
      if (scriptPick) {
        if (scriptPick->i >= w || scriptPick->j >= h)
          throw io::InputError(o.script + ": pick: pixel (" + std::to_string(scriptPick->i) + ", " +
                               std::to_string(scriptPick->j) + ") is outside the " + std::to_string(w) + " x " +
                               std::to_string(h) + " framebuffer");
        const Pick picked = pickPixel(api, renderer, cam, target, *pickTable, *scriptPick);
        std::printf("%s\n", pickJson(picked).c_str());
        status.picked = describePick(picked);
      }
      api.BlitNamedFramebuffer(target.colorFramebuffer(), 0, 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT,
                               GL_NEAREST);
      api.BindFramebuffer(GL_FRAMEBUFFER, 0);
      api.Viewport(0, 0, w, h);
    }
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window);
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  std::fprintf(stderr,
               "tensorglyph view: %zu frames, median period %.2f ms; %zu parameter changes, CPU time per change "
               "median %.2f us, max %.2f us\n",
               frameMs.size(), median(frameMs), changeUs.size(), median(changeUs),
               changeUs.empty() ? 0.0 : *std::max_element(changeUs.begin(), changeUs.end()));
  return 0;
}

}  // namespace tg::app
