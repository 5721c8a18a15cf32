// Tier 2 (GL-free): anatomical views, orientation letters and slices in
// anatomical terms (issue 32 items 1 and 2).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "app/view_script.h"
#include "io/core/selection.h"
#include "render/legend/orientation_pass.h"
#include "view/anatomy.h"

using namespace tg;

namespace {

// The image's right and up in WC for a named view.
struct Screen {
  glm::dvec3 right, up;
};
Screen screenOf(const char* view, bool radiological) {
  const render::ViewAxes a = *render::namedView(view, radiological);
  return {glm::cross(a.upWC, a.towardEyeWC), a.upWC};
}

}  // namespace

TEST(Anatomy, ViewsPutTheSidesWhereEachConventionDoes) {
  struct Case {
    const char* view;
    bool radiological;
    const char *right, *up;
  } cases[] = {{"axial", false, "R", "A"},    {"axial", true, "L", "A"},    {"coronal", false, "R", "S"},
               {"coronal", true, "L", "S"},   {"sagittal", false, "P", "S"}, {"sagittal", true, "P", "S"},
               {"superior", true, "R", "A"},  {"inferior", false, "L", "A"}, {"anterior", false, "L", "S"},
               {"posterior", true, "R", "S"}, {"left", false, "P", "S"},     {"right", false, "A", "S"}};
  for (const Case& c : cases) {
    const Screen s = screenOf(c.view, c.radiological);
    EXPECT_EQ(render::orientationLetters(s.right), c.right) << c.view << (c.radiological ? " radiological" : "");
    EXPECT_EQ(render::orientationLetters(s.up), c.up) << c.view;
  }
  EXPECT_FALSE(render::namedView("up", false));
}

TEST(Anatomy, ObliqueDirectionsGetTwoLetters) {
  EXPECT_EQ(render::orientationLetters({-1, 0, 0}), "L");
  EXPECT_EQ(render::orientationLetters({0.2, -1, 0}), "P");     // 11 degrees off: one letter
  EXPECT_EQ(render::orientationLetters({0.6, 0, -1}), "IR");    // 31 degrees off: two, the larger first
  EXPECT_EQ(render::orientationLetters({0, 0, 0}), "");
  EXPECT_TRUE(render::isAnatomicalSpace("RAS (converted from left-posterior-superior)"));
  EXPECT_FALSE(render::isAnatomicalSpace(""));
  EXPECT_FALSE(render::isAnatomicalSpace("voxel grid (no sform or qform)"));
}

TEST(Anatomy, FaceOnLooksAlongTheNormalWithThePlanesUp) {
  // small_64D's k axis: superior, tilted 14 degrees towards posterior.
  const glm::dvec3 n = glm::normalize(glm::dvec3(0, -0.487, 1.94));
  for (const bool radiological : {false, true}) {
    const render::ViewAxes v = render::faceOnView(n, radiological);
    EXPECT_NEAR(std::abs(glm::dot(v.towardEyeWC, n)), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(v.upWC, v.towardEyeWC), 0.0, 1e-12);
    EXPECT_EQ(render::orientationLetters(v.upWC), "A");  // axial: anterior up
    EXPECT_EQ(render::orientationLetters(glm::cross(v.upWC, v.towardEyeWC)), radiological ? "L" : "R");
  }
}

TEST(Anatomy, SlicesParseInVoxelAnatomicalAndWorldTerms) {
  EXPECT_EQ(io::parseSlice("x:5"), (io::SliceSpec{0, 5, 1}));  // voxel axis i, as ever
  EXPECT_EQ(io::parseSlice("k:5:3"), (io::SliceSpec{2, 5, 3}));
  const io::SliceSpec axial = io::parseSlice("axial:40:5");
  EXPECT_EQ(axial.worldAxis, 2);
  EXPECT_EQ(axial.index, 40);
  EXPECT_EQ(axial.thickness, 5);
  EXPECT_EQ(axial.text(), "axial:40:5");
  const io::SliceSpec world = io::parseSlice("z=12.5mm");
  EXPECT_EQ(world.worldAxis, 2);
  EXPECT_EQ(world.positionWC, 12.5);
  EXPECT_EQ(world.text(), "z=12.5");
  EXPECT_EQ(io::parseSlice("coronal=-3:2").text(), "y=-3:2");
  for (const char* bad : {"q:3", "i=3", "z=", "z=mm", "z=1e999", "axial:-1", "z:1.5", "axial", "z=3:0"})
    EXPECT_THROW(io::parseSlice(bad), std::invalid_argument) << bad;
}

TEST(Anatomy, SlicesResolveToTheNearestVoxelAxisOnAnObliqueGrid) {
  // small_64D's affine: i runs posterior (and 14 degrees inferior), j left, k superior.
  io::GridPlacement p;
  const double axes[9] = {0, -2, 0, -1.94, 0, -0.487, -0.487, 0, 1.94};
  std::copy(axes, axes + 9, p.axesWC);
  p.originWC[0] = 20, p.originWC[1] = 25.171, p.originWC[2] = 12.32;
  const int dims[3] = {10, 10, 10};
  EXPECT_EQ(io::resolveSlice(io::parseSlice("axial:5"), p, dims).axis, 2);
  EXPECT_EQ(io::resolveSlice(io::parseSlice("coronal:5"), p, dims).axis, 0);
  EXPECT_EQ(io::resolveSlice(io::parseSlice("sagittal:5"), p, dims).axis, 1);
  EXPECT_EQ(io::resolveSlice(io::parseSlice("x:5"), p, dims), io::parseSlice("x:5"));
  // z at voxel (4.5, 4.5, k) is 12.32 - 0.487 x 4.5 + 1.94 k.
  for (int k : {0, 3, 9}) {
    const double z = 12.32 - 0.487 * 4.5 + 1.94 * k + 0.4;
    const io::SliceSpec s = io::resolveSlice(io::parseSlice("z=" + std::to_string(z)), p, dims);
    EXPECT_EQ(s.axis, 2);
    EXPECT_EQ(s.index, k) << z;
  }
  EXPECT_LT(io::resolveSlice(io::parseSlice("z=-1000"), p, dims).index, 0);
  EXPECT_EQ(io::resolveSlice(io::parseSlice("z=1e300"), p, dims).index, 1000000000000000LL);
}

TEST(Anatomy, ScriptTurnsTheViewAndSwapsTheConvention) {
  render::CameraDesc d;
  d.eyeWC = {0, 0, 10};
  app::ViewState v{{}, app::OrbitCamera(d), 1.0, 1.0};
  auto step = [&](const std::string& verb, const std::string& arg) { app::applyStep({1, verb, {arg}}, v); };
  auto right = [&] {
    const render::CameraDesc& c = v.camera.desc();
    return render::orientationLetters(glm::cross(glm::normalize(c.lookAtWC - c.eyeWC), c.upWC));
  };
  step("view", "coronal");
  EXPECT_EQ(right(), "R");
  EXPECT_NEAR(glm::length(v.camera.desc().eyeWC - v.camera.desc().lookAtWC), 10.0, 1e-12);  // distance kept
  step("convention", "radiological");
  EXPECT_EQ(right(), "L");  // coronal again, facing the patient
  step("view", "sagittal");
  step("convention", "neurological");
  EXPECT_EQ(right(), "P");  // sagittal is alike in both
  EXPECT_FALSE(v.params.orientationLetters);
  step("letters", "on");
  EXPECT_TRUE(v.params.orientationLetters);
}

TEST(Anatomy, LettersSitAtTheEdgesTheyName) {
  render::CameraDesc d;
  const render::ViewAxes a = *render::namedView("coronal", true);
  d.eyeWC = 50.0 * a.towardEyeWC;
  d.upWC = a.upWC;
  const render::Camera cam = render::makeCamera(d, 400, 300, glm::dvec3(-1), glm::dvec3(1));
  const render::LegendFont font(2);
  const render::LegendLayout l = render::layoutOrientation(cam, font);
  ASSERT_EQ(l.labels.size(), 4u);
  ASSERT_EQ(l.swatches.size(), 4u);
  const char* want[4] = {"R", "L", "S", "I"};  // left, right, top, bottom
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(l.labels[k].text, want[k]);
    const render::LegendRect& r = l.labels[k].rect;
    EXPECT_GE(r.x0, 0);
    EXPECT_LE(r.x1, 400);
    EXPECT_GE(r.y0, 0);
    EXPECT_LE(r.y1, 300);
    const render::LegendRect& b = l.swatches[k].rect;
    EXPECT_TRUE(b.x0 <= r.x0 && b.x1 >= r.x1 && b.y0 <= r.y0 && b.y1 >= r.y1) << "backing under " << want[k];
  }
  EXPECT_LT(l.labels[0].rect.x1, 40);   // at the left edge, halfway down
  EXPECT_NEAR(0.5 * (l.labels[0].rect.y0 + l.labels[0].rect.y1), 150, 2);
  EXPECT_GT(l.labels[1].rect.x0, 360);
  EXPECT_LE(l.labels[2].rect.y1, 40);
  EXPECT_GE(l.labels[3].rect.y0, 260);
}

TEST(Anatomy, LettersSlideClearOfTheLegend) {
  render::CameraDesc d;
  const render::ViewAxes a = *render::namedView("coronal", true);
  d.eyeWC = 50.0 * a.towardEyeWC;
  d.upWC = a.upWC;
  const render::Camera cam = render::makeCamera(d, 400, 300, glm::dvec3(-1), glm::dvec3(1));
  const render::LegendFont font(2);
  const render::LegendRect panel{300, 90, 396, 296};  // a tall panel in the bottom-right corner
  const render::LegendLayout free = render::layoutOrientation(cam, font);
  const render::LegendLayout l = render::layoutOrientation(cam, font, panel);
  auto meets = [&](const render::LegendRect& r) {
    return r.x0 < panel.x1 && panel.x0 < r.x1 && r.y0 < panel.y1 && panel.y0 < r.y1;
  };
  ASSERT_TRUE(meets(free.swatches[1].rect));  // the right letter would sit on the panel
  for (int k = 0; k < 4; ++k) EXPECT_FALSE(meets(l.swatches[k].rect)) << l.labels[k].text;
  EXPECT_EQ(l.labels[1].rect.x0, free.labels[1].rect.x0);  // still at the right edge,
  EXPECT_LT(l.labels[1].rect.y1, panel.y0);                 // above the panel
  EXPECT_GE(l.swatches[1].rect.y0, 0);
  for (int k : {0, 2, 3}) EXPECT_EQ(l.labels[k].rect.y0, free.labels[k].rect.y0);  // the others unmoved
  EXPECT_EQ(l.labels[3].rect.x0, free.labels[3].rect.x0);
  // A panel along the whole bottom edge moves the bottom letter nowhere: no side has room.
  const render::LegendRect strip{0, 250, 400, 300};
  const render::LegendLayout s = render::layoutOrientation(cam, font, strip);
  EXPECT_EQ(s.labels[3].rect.x0, free.labels[3].rect.x0);
}
