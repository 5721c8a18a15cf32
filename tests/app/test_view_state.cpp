// Tier 2 (GL-free): the viewer's camera and script state.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/scale/cli_values.h"
#include "app/render_options.h"
#include "app/script_commands.h"
#include "app/view_script.h"
#include "io/field/tensor_field.h"

using namespace tg;

namespace {

render::CameraDesc start() {
  render::CameraDesc d;
  d.eyeWC = {4, -3, 2};
  d.lookAtWC = {1, 1, 0};
  d.upWC = {0, 0, 1};
  return d;
}

// The message of the io::InputError that f throws; a test failure, and "",
// where it throws none.
template <class F>
std::string inputErrorOf(F f, const std::string& what) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for " << what;
  return "";
}

// Each test writes its script to `path`, in a directory of its own.
class ViewScript : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("tg_view_" + std::string(t->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    path = (dir_ / "s.txt").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // parseScript's error for a script of `text` alone.
  std::string scriptError(const std::string& text) {
    std::ofstream(path) << text;
    return inputErrorOf([&] { app::parseScript(path); }, text);
  }

  std::string path;

 private:
  std::filesystem::path dir_;
};

}  // namespace

TEST(OrbitCamera, TurnsAboutTheTargetAndStopsShortOfThePole) {
  app::OrbitCamera c(start());
  const double r = glm::length(start().eyeWC - start().lookAtWC);
  for (int k = 0; k < 8; ++k) c.orbit(45, 0);
  EXPECT_LT(glm::length(c.desc().eyeWC - start().eyeWC), 1e-9 * r) << "eight 45-degree turns are one turn";
  c.orbit(30, 10);
  EXPECT_NEAR(glm::length(c.desc().eyeWC - c.desc().lookAtWC), r, 1e-9 * r);
  EXPECT_NE(glm::length(c.desc().eyeWC - start().eyeWC), 0.0);
  c.orbit(0, 1000);  // past the pole: clamped, and the view keeps an up vector
  EXPECT_STREQ(render::validateCamera(c.desc()), "");
  const glm::dvec3 dir = glm::normalize(c.desc().eyeWC - c.desc().lookAtWC);
  EXPECT_NEAR(glm::degrees(std::acos(dir.z)), 1.0, 1e-6);
  c.reset();
  EXPECT_EQ(c.desc().eyeWC, start().eyeWC);
}

TEST(OrbitCamera, PanKeepsTheViewDirectionAndZoomTheDirection) {
  app::OrbitCamera c(start());
  const glm::dvec3 v0 = start().lookAtWC - start().eyeWC;
  c.pan(0.25, -0.1);
  const glm::dvec3 shift = c.desc().lookAtWC - start().lookAtWC;
  EXPECT_LT(glm::length(c.desc().lookAtWC - c.desc().eyeWC - v0), 1e-12);
  EXPECT_NEAR(glm::dot(shift, v0), 0.0, 1e-9);
  EXPECT_GT(glm::length(shift), 0.0);
  c.reset();
  c.zoom(2.0);
  EXPECT_NEAR(glm::length(c.desc().lookAtWC - c.desc().eyeWC), 0.5 * glm::length(v0), 1e-12);
  EXPECT_LT(glm::length(glm::normalize(c.desc().lookAtWC - c.desc().eyeWC) - glm::normalize(v0)), 1e-12);
}

TEST_F(ViewScript, ParsesAppliesAndNamesTheLineOfAMistake) {
  std::ofstream(path) << "# comment\n\nscale 2   # twice\nslab j:2\nlight key 0.7\nglyph superquadric\n"
                         "stats on\nfa-min 0.4\nslab off\n";
  const auto steps = app::parseScript(path);
  ASSERT_EQ(steps.size(), 7u);
  EXPECT_EQ(steps[0].line, 3);
  app::ViewState v{{}, app::OrbitCamera(start()), 0.5, 1.0};
  v.fieldGrid = app::SliceGrid{{}, {5, 5, 5}};  // unit voxels at 0..4
  for (std::size_t k = 0; k < 6; ++k) app::applyStep(steps[k], v);
  EXPECT_DOUBLE_EQ(v.params.scale, 1.0);
  EXPECT_EQ(v.params.slab.axis, 1);
  EXPECT_EQ(v.params.slab.lo, 1.75);  // the slice's centres, a quarter voxel wider each side
  EXPECT_EQ(v.params.slab.hi, 2.25);
  EXPECT_EQ(v.params.slab.normalWC, glm::dvec3(0.0)) << "across a world axis: the axis form";
  EXPECT_FLOAT_EQ(v.params.light.key, 0.7f);
  EXPECT_EQ(v.params.glyph, render::GlyphKind::Superquadric);
  EXPECT_TRUE(v.params.iterationStats);
  EXPECT_DOUBLE_EQ(v.params.faMin, 0.4);
  EXPECT_EQ(v.slabSlice->text(), "y:2");  // voxel axis j, canonically
  app::applyStep(steps[6], v);
  EXPECT_EQ(v.params.slab.axis, -1);
  EXPECT_FALSE(v.slabSlice);

  EXPECT_PRED_FORMAT2(testing::IsSubstring, path + ":3: slab: give a slice as --slice takes it, or off",
                      scriptError("zoom 2\n\nslab z 3 1\n"));
}

TEST_F(ViewScript, MagnitudeAndClampResolveTheSizeAgainWithoutTheRecords) {
  std::ofstream(path) << "magnitude log\nclamp 0\nmagnitude shape 2.5\nscale 3\nclamp 1.5\nmagnitude linear\n";
  const auto steps = app::parseScript(path);
  ASSERT_EQ(steps.size(), 6u);
  // Magnitudes 1, 2, ..., 100 at sample spacing 0.5, as the viewer keeps them.
  app::ViewState v{{}, app::OrbitCamera(start()), 1.0, 1.0};
  v.magnitudes.spacing = 0.5;
  for (int k = 1; k <= 100; ++k) v.magnitudes.sorted.push_back(k);
  v.magnitudes.maxAbs = 100;
  app::resize(v);
  EXPECT_DOUBLE_EQ(v.params.scale * 90.0, 0.25);  // the 90th percentile is one spacing across
  EXPECT_DOUBLE_EQ(v.params.sizing.maxRadiusWC, 0.5);  // the default clamp: 2 spacings
  app::applyStep(steps[0], v);
  EXPECT_EQ(v.params.sizing.magnitude, tensor::Magnitude::Log);
  EXPECT_DOUBLE_EQ(v.params.sizing.lambda0, 51.0);  // the median
  app::applyStep(steps[1], v);
  EXPECT_EQ(v.params.sizing.maxRadiusWC, 0.0);
  app::applyStep(steps[2], v);
  EXPECT_EQ(v.params.sizing.magnitude, tensor::Magnitude::Shape);
  EXPECT_DOUBLE_EQ(v.params.sizing.lambda0, 2.5);
  EXPECT_DOUBLE_EQ(v.params.scale * 2.5, 0.25);
  app::applyStep(steps[3], v);
  EXPECT_DOUBLE_EQ(v.params.scale * 2.5, 0.75);  // the scale factor stays on top of the mapping
  app::applyStep(steps[4], v);
  EXPECT_DOUBLE_EQ(v.params.sizing.maxRadiusWC, 0.375);
  EXPECT_DOUBLE_EQ(v.params.scale * 2.5, 0.75);
  app::applyStep(steps[5], v);
  EXPECT_EQ(v.params.sizing.magnitude, tensor::Magnitude::Linear);

  for (const auto& [line, what] : {std::pair{"magnitude cubic\n", "unknown mapping"},
                                   std::pair{"magnitude linear 2\n", "LAMBDA0 applies to log or shape only"},
                                   std::pair{"magnitude log 0\n", "magnitude LAMBDA0 must be within"},
                                   std::pair{"clamp -1\n", "clamp must be within"}}) {
    EXPECT_PRED_FORMAT2(testing::IsSubstring, what, scriptError(line));
  }
}

TEST_F(ViewScript, LegendCommandsSetTheLegendParameters) {
  std::ofstream(path) << "legend on\nlegend-corner top-left\nunits MPa\nlength-units mm\nlegend off\n";
  const auto steps = app::parseScript(path);
  ASSERT_EQ(steps.size(), 5u);
  app::ViewState v{{}, app::OrbitCamera(start()), 1.0, 1.0};
  EXPECT_FALSE(v.params.legend.enabled);  // off unless asked for
  for (std::size_t k = 0; k < 4; ++k) app::applyStep(steps[k], v);
  EXPECT_TRUE(v.params.legend.enabled);
  EXPECT_EQ(v.params.legend.corner, render::LegendCorner::TopLeft);
  EXPECT_EQ(v.params.legend.units, "MPa");
  EXPECT_EQ(v.params.legend.lengthUnits, "mm");
  app::applyStep(steps[4], v);
  EXPECT_FALSE(v.params.legend.enabled);
  for (const auto& [text, message] : {std::pair<std::string, std::string>{"legend maybe\n", "legend: on or off"},
                                      {"legend-corner middle\n", "legend-corner: unknown corner \"middle\""},
                                      {"units " + std::string(41, 'u') + "\n", "units: at most 40 characters"}}) {
    EXPECT_PRED_FORMAT2(testing::IsSubstring, path + ":1: " + message, scriptError(text));
  }
}

TEST_F(ViewScript, DepthCueCommandsSetTheirParametersWithinRange) {
  std::ofstream(path) << "ao on\nao-radius 0.25\nao-strength 2\noutlines on\noutline-width 3\nao off\n";
  const auto steps = app::parseScript(path);
  ASSERT_EQ(steps.size(), 6u);
  app::ViewState v{{}, app::OrbitCamera(start()), 1.0, 1.0};
  EXPECT_EQ(v.params.ao, render::AoParams{});
  EXPECT_FALSE(v.params.ao.enabled);
  EXPECT_FALSE(v.params.outline.enabled);
  for (std::size_t k = 0; k < 5; ++k) app::applyStep(steps[k], v);
  EXPECT_TRUE(v.params.ao.enabled);
  EXPECT_DOUBLE_EQ(v.params.ao.radius, 0.25);
  EXPECT_DOUBLE_EQ(v.params.ao.strength, 2.0);
  EXPECT_TRUE(v.params.outline.enabled);
  EXPECT_DOUBLE_EQ(v.params.outline.width, 3.0);
  app::applyStep(steps[5], v);
  EXPECT_FALSE(v.params.ao.enabled);
  EXPECT_DOUBLE_EQ(v.params.ao.radius, 0.25) << "switching off keeps the tuning";

  const std::pair<const char*, const char*> bad[] = {{"ao maybe\n", ":1: ao: on or off"},
                                                     {"ao-radius 0\n", ":1: ao-radius must be within 1.2e-38..3.4e+38"},
                                                     {"ao-strength 9\n", ":1: ao-strength must be within 0..4"},
                                                     {"outline-width 20\n", ":1: outline-width must be within 0.25..8"},
                                                     {"outlines\n", ":1: outlines: wrong number of arguments"}};
  for (const auto& [text, message] : bad)
    EXPECT_EQ(scriptError(text), path + message) << text;
}

TEST_F(ViewScript, ShadowCommandsSetTheShadowParamsWithRenderRanges) {
  std::ofstream(path) << "shadows on\nshadow penumbra 0.01\nshadow strength 0.5\nshadow bias 2\nshadow map-size 512\n"
                         "shadows off\n";
  const auto steps = app::parseScript(path);
  ASSERT_EQ(steps.size(), 6u);
  app::ViewState v{{}, app::OrbitCamera(start()), 1.0, 1.0};
  EXPECT_FALSE(v.params.shadow.enabled);  // off unless asked for
  for (std::size_t k = 0; k < 5; ++k) app::applyStep(steps[k], v);
  EXPECT_TRUE(v.params.shadow.enabled);
  EXPECT_FLOAT_EQ(v.params.shadow.penumbra, 0.01f);
  EXPECT_FLOAT_EQ(v.params.shadow.strength, 0.5f);
  EXPECT_FLOAT_EQ(v.params.shadow.bias, 2.0f);
  EXPECT_EQ(v.params.shadow.mapSize, 512);
  EXPECT_EQ(v.params.shadow.mapDensity, 0.0f);  // a size given is fixed
  app::applyStep(steps[5], v);
  EXPECT_FALSE(v.params.shadow.enabled);

  const std::pair<const char*, const char*> bad[] = {
      {"shadows maybe\n", ":1: shadows: on or off"},
      {"shadow strength 1.5\n", ":1: shadow strength must be within 0..1"},
      {"shadow map-size 100000\n", ":1: shadow map-size must be within 64..8192"},
      {"shadow softness 1\n", ":1: shadow: unknown parameter \"softness\""},
      {"shadow penumbra\n", ":1: shadow: wrong number of arguments"}};
  for (const auto& [text, what] : bad)
    EXPECT_PRED_FORMAT2(testing::IsSubstring, what, scriptError(text));
}

TEST_F(ViewScript, PlaneStepsToggleAndMoveOnlyThePlanesTheViewHas) {
  std::ofstream(path) << "plane 1 off\nplane 2 index 7\nplane 3 off\nplane 1 on\nplane 2 index 0\n";
  const auto steps = app::parseScript(path);
  ASSERT_EQ(steps.size(), 5u);
  app::ViewState v{{}, app::OrbitCamera(start()), 1.0, 1.0};
  v.underlayGrid = app::SliceGrid{{}, {40, 30, 20}};
  render::PlaneSpec z, x, oblique;
  z.axis = 2;
  z.index = 3;
  x.axis = 0;
  x.index = 39;
  oblique.axis = -1;
  v.planes = {{z, true, 20}, {x, true, 40}, {oblique, true, 0}};
  EXPECT_NO_THROW(app::checkPlaneSteps(steps, v.planes, path));
  app::applyStep(steps[0], v);
  EXPECT_FALSE(v.planes[0].visible);
  EXPECT_EQ(v.planes[0].spec, z) << "switching off keeps the slice";
  app::applyStep(steps[1], v);
  EXPECT_EQ(v.planes[1].spec.index, 7);
  EXPECT_EQ(v.planes[1].spec.axis, 0);
  EXPECT_TRUE(v.planes[1].visible);
  app::applyStep(steps[2], v);
  EXPECT_FALSE(v.planes[2].visible);
  app::applyStep(steps[3], v);
  EXPECT_TRUE(v.planes[0].visible);
  app::applyStep(steps[4], v);
  EXPECT_EQ(v.planes[1].spec.index, 0);
  EXPECT_EQ(v.planes[0].spec, z) << "a step moves its own plane only";

  // Against the planes given: checked after the underlay is known, before the window opens.
  const std::pair<const char*, const char*> unfit[] = {
      {"plane 4 on\n", ":1: plane 4: the view has 3 slice plane(s), numbered from 1"},
      {"zoom 2\nplane 1 index 20\n", ":2: plane 1: index 20 is outside 0..19 along z"},
      {"plane 3 index 0\n", ":1: plane 3: an oblique plane (--plane-at) can only be switched on or off"}};
  for (const auto& [text, message] : unfit) {
    std::ofstream(path) << text;
    const auto ok = app::parseScript(path);
    EXPECT_PRED_FORMAT2(testing::IsSubstring, path + message,
                        inputErrorOf([&] { app::checkPlaneSteps(ok, v.planes, path); }, text));
  }
  std::ofstream(path) << "plane 1 on\n";
  EXPECT_PRED_FORMAT2(testing::IsSubstring, ":1: plane 1: the view has no slice planes",
                      inputErrorOf([&] { app::checkPlaneSteps(app::parseScript(path), {}, path); }, "no planes"));

  // Malformed steps: refused by parseScript itself.
  const std::pair<const char*, const char*> bad[] = {
      {"plane 0 on\n", ":1: plane: \"0\" is not an integer within 1..255"},
      {"plane 1 maybe\n", ":1: plane: give N on|off, N SLICE or N index I"},
      {"plane 1 move 3\n", ":1: plane: give N on|off, N SLICE or N index I"},
      {"plane 1 k:3:2\n", ":1: plane: k:3:2: a plane is one slice; give no :THICKNESS"},
      {"plane 1 q:3\n", ":1: plane: unknown axis \"q\""},
      {"plane 1 index -1\n", ":1: plane index: \"-1\" is not an integer within 0..2147483648"},
      {"plane 1\n", ":1: plane: wrong number of arguments"}};
  for (const auto& [text, message] : bad)
    EXPECT_PRED_FORMAT2(testing::IsSubstring, path + message, scriptError(text)) << text;

  // A SLICE as --slice takes it, on the underlay's grid: the plane turns to
  // the voxel axis it names.
  std::ofstream(path) << "plane 2 k:4\nplane 1 sagittal:12\nplane 2 z=7.2\n";
  const auto slices = app::parseScript(path);
  EXPECT_NO_THROW(app::checkPlaneSteps(slices, v.planes, path, v.underlayGrid));
  app::applyStep(slices[0], v);
  EXPECT_EQ(v.planes[1].spec.axis, 2);
  EXPECT_EQ(v.planes[1].spec.index, 4);
  EXPECT_EQ(v.planes[1].slices, 20);
  app::applyStep(slices[1], v);
  EXPECT_EQ(v.planes[0].spec.axis, 0);
  EXPECT_EQ(v.planes[0].spec.index, 12);
  EXPECT_EQ(v.planes[0].slices, 40);
  app::applyStep(slices[2], v);
  EXPECT_EQ(v.planes[1].spec.index, 7);
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {"plane 1 k:20\n", ":1: plane 1 k:20: index 20 is outside 0..19 along voxel axis k of the underlay's grid"},
           {"plane 1 z=-3\n", ":1: plane 1 z=-3: the position falls at index -3, outside 0..19 along voxel axis k"},
           {"plane 3 k:2\n", ":1: plane 3: an oblique plane (--plane-at) can only be switched on or off"}}) {
    std::ofstream(path) << text;
    const auto s = app::parseScript(path);
    EXPECT_PRED_FORMAT2(testing::IsSubstring, path + message,
                        inputErrorOf([&] { app::checkPlaneSteps(s, v.planes, path, v.underlayGrid); }, text));
  }
}

// `slab SLICE` keeps exactly the glyphs that --slice SLICE would load
// (io::Selector's voxels), on a grid whose axes are permuted and flipped and
// on small_64D's oblique one, in every form --slice takes.
TEST_F(ViewScript, SlabKeepsTheGlyphsASliceWouldLoadOnAnyGrid) {
  app::SliceGrid permuted{{}, {6, 7, 8}};
  const double flips[9] = {0, 0, -1.5, 2, 0, 0, 0, -1, 0};  // i along +y, j along -z, k along -x
  std::copy(flips, flips + 9, permuted.placement.axesWC);
  permuted.placement.originWC[0] = 10;
  app::SliceGrid oblique{{}, {10, 9, 8}};
  const double tilted[9] = {0, -2, 0, -1.94, 0, -0.487, -0.487, 0, 1.94};
  std::copy(tilted, tilted + 9, oblique.placement.axesWC);
  oblique.placement.originWC[0] = 20, oblique.placement.originWC[1] = 25.171, oblique.placement.originWC[2] = 12.32;
  for (const app::SliceGrid* g : {&permuted, &oblique})
    for (const std::string spec : {"i:2", "k:0:3", "j:6:2", "axial:3", "coronal:4:3", "sagittal:1", "x=9.5:2", "z=12"}) {
      std::ofstream(path) << "slab " << spec << "\n";
      const auto steps = app::parseScript(path);
      app::ViewState v{{}, app::OrbitCamera(start()), 1.0, 1.0};
      v.fieldGrid = *g;
      try {
        app::checkSlabSteps(steps, v.fieldGrid, path);
      } catch (const io::InputError&) {
        continue;  // a position outside this grid: refused, as --slice refuses it
      }
      app::applyStep(steps[0], v);
      const render::Slab& slab = v.params.slab;
      ASSERT_GE(slab.axis, 0) << spec;
      // The viewer panel's slab controls start from the slice as resolved.
      ASSERT_TRUE(v.slabSlice) << spec;
      EXPECT_EQ(v.slabSlice->worldAxis, io::parseSlice(spec).worldAxis) << spec;
      EXPECT_EQ(app::slabOf(*v.slabSlice, *g), slab) << spec;
      io::Selection sel;
      sel.slice = io::parseSlice(spec);
      const io::Selector selector(sel, "grid", g->dims, &g->placement);
      const glm::dvec3 dir = slab.direction();
      std::size_t kept = 0;
      for (int k = 0; k < g->dims[2]; ++k)
        for (int j = 0; j < g->dims[1]; ++j)
          for (int i = 0; i < g->dims[0]; ++i) {
            const double* m = g->placement.axesWC;
            double p[3];
            for (int r = 0; r < 3; ++r) p[r] = g->placement.originWC[r] + m[3 * r] * i + m[3 * r + 1] * j + m[3 * r + 2] * k;
            const std::uint64_t index = std::uint64_t(i) + std::uint64_t(g->dims[0]) * (j + std::uint64_t(g->dims[1]) * k);
            const bool slice = selector.judge(index, p) == io::Selector::Verdict::Keep;
            const double d = glm::dot(glm::dvec3(p[0], p[1], p[2]), dir);
            EXPECT_EQ(d >= slab.lo && d <= slab.hi, slice) << spec << " voxel " << i << " " << j << " " << k;
            kept += slice;
          }
      EXPECT_GT(kept, 0u) << spec;
    }
  // Errors name the line and the slice, and a point set has no slices.
  std::ofstream(path) << "zoom 2\nslab k:8\n";
  EXPECT_PRED_FORMAT2(testing::IsSubstring, path + ":2: slab k:8: index 8 is outside 0..7 along voxel axis k of the glyphs' grid",
                      inputErrorOf([&] { app::checkSlabSteps(app::parseScript(path), permuted, path); }, "k:8"));
  std::ofstream(path) << "slab axial:2\n";
  EXPECT_PRED_FORMAT2(testing::IsSubstring, path + ":1: slab axial:2: the glyphs are a point set",
                      inputErrorOf([&] { app::checkSlabSteps(app::parseScript(path), std::nullopt, path); }, "points"));
  EXPECT_PRED_FORMAT2(testing::IsSubstring, path + ":1: slab: unknown axis \"w\"", scriptError("slab w:1\n"));
  EXPECT_PRED_FORMAT2(testing::IsSubstring, path + ":1: slab: thickness must be at least 1", scriptError("slab k:1:0\n"));
}

TEST_F(ViewScript, MeshCommandsToggleAndSetTheModeOfOneMesh) {
  std::ofstream(path) << "mesh 1 off\nmesh 2 see-through\nmesh-opacity 2 0.6\nmesh 1 on\nmesh 1 edges\n";
  const auto steps = app::parseScript(path);
  ASSERT_EQ(steps.size(), 5u);
  app::ViewState v{{}, app::OrbitCamera(start()), 1.0, 1.0};
  v.meshes = {{"mesh a.stl", true, {}}, {"mesh b.vtp", true, {}}};
  for (std::size_t k = 0; k < 3; ++k) app::applyStep(steps[k], v);
  EXPECT_FALSE(v.meshes[0].visible);
  EXPECT_TRUE(v.meshes[1].visible);
  EXPECT_EQ(v.meshes[1].params.mode, render::MeshMode::SeeThrough);
  EXPECT_FLOAT_EQ(v.meshes[1].params.opacity, 0.6f);
  EXPECT_EQ(v.meshes[0].params, render::MeshParams{});  // the other mesh is untouched
  app::applyStep(steps[3], v);
  app::applyStep(steps[4], v);
  EXPECT_TRUE(v.meshes[0].visible);
  EXPECT_EQ(v.meshes[0].params.mode, render::MeshMode::Edges);
  app::checkScriptMeshes(steps, 2, path);
  EXPECT_PRED_FORMAT2(testing::IsSubstring, ":2: mesh: mesh 2 of 1 loaded",
                      inputErrorOf([&] { app::checkScriptMeshes(steps, 1, path); }, "mesh 2 of 1"));
  const std::pair<const char*, const char*> bad[] = {
      {"mesh 0 on\n", ":1: mesh: \"0\" is not an integer within 1..255"},
      {"mesh 1 glass\n", ":1: mesh: give on, off or a mode (opaque, see-through or edges)"},
      {"mesh-opacity 1 1.5\n", ":1: mesh-opacity must be within 0..1"},
      {"mesh 1\n", ":1: mesh: wrong number of arguments"}};
  for (const auto& [text, what] : bad)
    EXPECT_PRED_FORMAT2(testing::IsSubstring, what, scriptError(text));
}

namespace tg::app {
namespace {

// A script's value outside the range render's flag declares drew a blank or
// NaN-black screenshot with exit 0 (`fa-min 2`, `light key 1e300`): each
// value is held to the flag's range, in the flag's words, naming the command.
TEST_F(ViewScript, ValuesAreHeldToTheRangesRenderDeclares) {
  RenderOptions o;
  OptionTable render;
  addRenderOptions(render, o);
  for (const auto& [line, flag] : std::vector<std::pair<std::string, std::string>>{
           {"fa-min 2", "--fa-min"}, {"gamma -1", "--gamma"}, {"gamma 1e300", "--gamma"},
           {"iterations 5000", "--iterations"}, {"epsilon 1", "--epsilon"}, {"clamp 1e-40", "--clamp"},
           {"ao-strength 9", "--ao-strength"}, {"outline-width 20", "--outline-width"},
           {"shadow strength 1.5", "--shadow-strength"}, {"shadow bias 100", "--shadow-bias"},
           {"mesh-opacity 1 1.5", "--mesh-opacity"}}) {
    const OptionTable::Option* opt = render.find(flag);
    ASSERT_TRUE(opt && opt->numbers) << flag;
    const std::string err = scriptError(line + "\n");
    EXPECT_PRED_FORMAT2(testing::IsSubstring, " must be within " + opt->numbers->text(), err) << line;
    // The same words as the flag's own refusal.
    const std::string value = line.substr(line.rfind(' ') + 1);
    try {
      std::vector<std::string> values(opt->arity(), value);
      OptionTable::apply(*opt, values);
      ADD_FAILURE() << flag << " " << value << " was accepted";
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()), flag + " must be within " + opt->numbers->text());
    }
  }
  for (const std::string line : {"light key 1e300", "light ambient -1", "light specular 2", "light shininess 0",
                                 "zoom 1e-40", "scale 1e300", "frames 0", "frames 100001",
                                 "pick -1 3", "pick 3 16384"})
    EXPECT_PRED_FORMAT2(testing::IsSubstring, "must be within", scriptError(line + "\n")) << line;
  std::ofstream(path) << "fa-min 1\nlight key 1\nlight shininess 200\nframes 100000\npick 16383 0\n";
  const std::vector<app::ScriptStep> steps = app::parseScript(path);
  ASSERT_EQ(steps.size(), 5u);
  EXPECT_EQ(steps[3].integer(0), 100000);
  EXPECT_EQ(steps[4].integer(0), 16383);
}

}  // namespace
}  // namespace tg::app

// The command table is the parser's: each row's verb is known, held to the
// row's argument counts, and in the reference that `help script` prints.
TEST_F(ViewScript, TheCommandTableIsWhatTheParserTakes) {
  const std::string reference = app::scriptReference(false), markdown = app::scriptReference(true);
  for (const app::ScriptCommand& c : app::scriptCommands()) {
    for (const int n : {c.minArgs - 1, c.maxArgs + 1}) {
      if (n < 0) continue;
      std::string line = c.verb;
      for (int k = 0; k < n; ++k) line += " 1";
      const std::string err = scriptError(line + "\n");
      EXPECT_EQ(err.find("unknown command"), std::string::npos) << line;
      EXPECT_PRED_FORMAT2(testing::IsSubstring, "arguments", err) << line;
    }
    EXPECT_NE(reference.find("\n  " + c.verb + (c.args.empty() ? "\n" : " ")), std::string::npos) << c.verb;
    EXPECT_NE(markdown.find("| `" + c.verb + "` |"), std::string::npos) << c.verb;
  }
  EXPECT_EQ(app::scriptCommand("spin"), nullptr);
  EXPECT_PRED_FORMAT2(testing::IsSubstring, "unknown command \"spin\"", scriptError("spin 3\n"));
}

TEST_F(ViewScript, ColourModeMapAndWindow) {
  std::ofstream(path) << "color vonmises\ncolormap gray\ncolor-range -2 5.5\ncolormap auto\ncolor-range auto\n";
  const auto steps = app::parseScript(path);
  ASSERT_EQ(steps.size(), 5u);
  app::ViewState v{{}, app::OrbitCamera(start()), 1.0, 1.0};
  for (std::size_t k = 0; k < 3; ++k) app::applyStep(steps[k], v);
  EXPECT_EQ(v.params.color, render::ColorMode::VonMises);
  EXPECT_EQ(v.params.colormap, render::Colormap::Gray);
  EXPECT_EQ(v.params.colorWindow, glm::dvec2(-2.0, 5.5));
  app::applyStep(steps[3], v);
  app::applyStep(steps[4], v);
  EXPECT_FALSE(v.params.colormap);
  EXPECT_FALSE(v.params.colorWindow);
  EXPECT_EQ(scriptError("color-range 3 3\n"), path + ":1: color-range: LO must be below HI");
  EXPECT_EQ(scriptError("colormap jet\n"),
            path + ":1: colormap: unknown map \"jet\"; choose auto, gray, viridis or diverging");
  EXPECT_NE(scriptError("color-range nan 1\n").find("color-range"), std::string::npos);
}
