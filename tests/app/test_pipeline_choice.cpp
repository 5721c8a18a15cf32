// Tier 2: --pipeline auto's choice from a fixed table, the table's strict
// text, and the fit (app/scale/pipeline_choice.h, pipeline_calibration.h).
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <stdexcept>
#include <string>

#include "app/scale/pipeline_calibration.h"
#include "app/scale/pipeline_choice.h"

using namespace tg;
using app::CostClass;
using render::GlyphKind;

namespace {

// Shaped like this project's 2-core llvmpipe measurement: the raster path
// pays more per glyph, the cpu path a little more per pixel, and the
// compute path (llvmpipe's compute shaders) most of all.
app::PathCalibration fixedTable() {
  return {"test renderer | 1.0 | 2 cores | LP_NUM_THREADS unset",
          {{"raster", CostClass::ClosedForm, {2.0, 1.0, 30.0}},
           {"raster", CostClass::March, {2.0, 1.7, 100.0}},
           {"cpu", CostClass::ClosedForm, {1.0, 0.16, 45.0}},
           {"cpu", CostClass::March, {1.0, 0.37, 110.0}},
           {"compute", CostClass::ClosedForm, {3.0, 1.6, 200.0}},
           {"compute", CostClass::March, {3.0, 11.0, 450.0}}}};
}

std::string errorOf(const std::string& text) {
  try {
    app::parseCalibrations(text, "cache.tsv");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PipelineChoice, TheFasterPredictionWinsAndTheChoiceIsDeterministic) {
  const app::PathCalibration t = fixedTable();
  // 2,600 march glyphs at 1024x768: raster 2 + 4.4 + 78.6 = 85.0 ms, cpu 1 + 1.0 + 86.5 = 88.5 ms,
  // compute 3 + 28.6 + 353.9 = 385.5 ms.
  const app::PathChoice small = app::choosePath(&t, GlyphKind::Superquadric, 3.0, 2600, 1024 * 768);
  EXPECT_EQ(small.path, "raster") << small.why;
  EXPECT_NE(small.why.find("predicted 85 ms a frame against cpu 88 ms, compute 385 ms"), std::string::npos) << small.why;
  // 2 M glyphs at 1920x1080: raster 3.6 s, cpu 0.97 s.
  const app::PathChoice brain = app::choosePath(&t, GlyphKind::Superquadric, 3.0, 2e6, 1920 * 1080);
  EXPECT_EQ(brain.path, "cpu") << brain.why;
  EXPECT_NE(brain.why.find("2000000 march glyphs"), std::string::npos) << brain.why;
  for (int k = 0; k < 3; ++k) EXPECT_EQ(app::choosePath(&t, GlyphKind::Superquadric, 3.0, 2e6, 1920 * 1080).path, "cpu");
  // At gamma 0 superquadrics cost what ellipsoids cost.
  EXPECT_EQ(app::costClassOf(GlyphKind::Superquadric, 0.0), CostClass::ClosedForm);
  EXPECT_EQ(app::costClassOf(GlyphKind::Superquadric, 0.5), CostClass::March);
  EXPECT_EQ(app::costClassOf(GlyphKind::Ellipsoid, 3.0), CostClass::ClosedForm);
  const app::PathChoice ell = app::choosePath(&t, GlyphKind::Superquadric, 0.0, 2e4, 800 * 600);
  EXPECT_NE(ell.why.find("closed-form"), std::string::npos) << ell.why;
}

TEST(PipelineChoice, KindsOnOnePathNeedNoCalibration) {
  EXPECT_FALSE(app::choiceNeedsCalibration(GlyphKind::Blob, {}));
  EXPECT_TRUE(app::choiceNeedsCalibration(GlyphKind::Ellipsoid, {}));
  EXPECT_TRUE(app::choiceNeedsCalibration(GlyphKind::Cylinder, {}));
  EXPECT_EQ(app::choosePath(nullptr, GlyphKind::Blob, 3.0, 10, 100).path, "cpu");
  // A viewer script that switches to blobs keeps even a tiny field on the
  // cpu path, the only one that draws both.
  const app::PathCalibration t = fixedTable();
  EXPECT_EQ(app::choosePath(&t, GlyphKind::Superquadric, 3.0, 10, 1024 * 768).path, "raster");
  EXPECT_EQ(app::choosePath(&t, GlyphKind::Superquadric, 3.0, 10, 1024 * 768, {GlyphKind::Blob}).path, "cpu");
  EXPECT_FALSE(app::choiceNeedsCalibration(GlyphKind::Box, {GlyphKind::Blob}));
  // Teem's boxes cost what closed forms cost.
  EXPECT_EQ(app::choosePath(&t, GlyphKind::Box, 0.0, 2e6, 1920 * 1080).path, "cpu");
  EXPECT_THROW(app::choosePath(nullptr, GlyphKind::Ellipsoid, 0.0, 10, 100), std::invalid_argument);
  app::PathCalibration partial = t;
  partial.rows.erase(partial.rows.begin() + 3);  // no cpu march row
  EXPECT_THROW(app::choosePath(&partial, GlyphKind::Superquadric, 3.0, 10, 100), std::invalid_argument);
  EXPECT_EQ(app::choosePath(&partial, GlyphKind::Ellipsoid, 0.0, 10, 100).path, "cpu");
}

TEST(PipelineChoice, TheCacheTextRoundTripsAndIsReadStrictly) {
  const app::PathCalibration t = fixedTable();
  app::PathCalibration other = t;
  other.key = "another GPU | 4.6 | 16 cores | LP_NUM_THREADS unset";
  const std::string text = app::formatCalibrations({t, other});
  const auto back = app::parseCalibrations(text, "cache.tsv");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].key, other.key);
  ASSERT_EQ(back[0].rows.size(), 6u);
  EXPECT_DOUBLE_EQ(back[0].cost("compute", CostClass::March)->glyphUs, 11.0);
  EXPECT_DOUBLE_EQ(back[0].cost("cpu", CostClass::March)->glyphUs, 0.37);
  EXPECT_DOUBLE_EQ(back[0].cost("raster", CostClass::ClosedForm)->megapixelMs, 30.0);

  const std::size_t headerEnd = text.find('\n', text.find('\n') + 1) + 1;
  const std::string head = text.substr(0, headerEnd);
  const std::string row = "k\traster\tmarch\t1\t2\t3\n";
  EXPECT_EQ(errorOf(head + row), "");
  EXPECT_NE(errorOf("hello\n").find("cache.tsv:1: is not a tensorglyph calibration cache"), std::string::npos);
  // Cut short: the line it stops in is named.
  const std::string cut = text.substr(0, text.size() - 1);
  const std::string lastLine = std::to_string(std::count(cut.begin(), cut.end(), '\n') + 1);
  EXPECT_NE(errorOf(cut).find("cache.tsv:" + lastLine + ": does not end with a line break"), std::string::npos) << errorOf(cut);
  EXPECT_NE(errorOf(head + "k\traster\tma").find("cache.tsv:3: does not end with a line break"), std::string::npos);
  EXPECT_NE(errorOf("\x01\x02 binary").find("cache.tsv:1: is not a tensorglyph calibration cache"), std::string::npos);
  EXPECT_NE(errorOf("").find("cache.tsv:1: is not a tensorglyph calibration cache"), std::string::npos);
  EXPECT_NE(errorOf(head.substr(0, head.find('\n') + 1) + row).find("cache.tsv:2: the column line"), std::string::npos);
  EXPECT_NE(errorOf(head + "k\traster\tmarch\t1\t2\n").find("cache.tsv:3: has 5 fields; a row has 6"), std::string::npos);
  EXPECT_NE(errorOf(head + "k\ttiles\tmarch\t1\t2\t3\n").find("cache.tsv:3: unknown glyph path \"tiles\""), std::string::npos);
  EXPECT_NE(errorOf(head + "k\tcpu\tcheap\t1\t2\t3\n").find("cache.tsv:3: unknown class \"cheap\""), std::string::npos);
  for (const char* bad : {"-1", "nan", "inf", "1e9", "2,5", "0x10", ""})
    EXPECT_NE(errorOf(head + "k\tcpu\tmarch\t1\t" + bad + "\t3\n").find("cache.tsv:3: field 5"), std::string::npos) << bad;
  EXPECT_NE(errorOf(head + row + row).find("cache.tsv:4: repeats the raster march row"), std::string::npos);
  EXPECT_NE(errorOf(head + "\traster\tmarch\t1\t2\t3\n").find("cache.tsv:3: has no key"), std::string::npos);
  EXPECT_NE(errorOf(head + std::string(70000, 'x') + "\n").find("a calibration cache holds at most"), std::string::npos);
  // Keys keep no tab or line break that would break a row.
  EXPECT_EQ(app::calibrationKey("a\tb\nc", "4.5", 2, ""), "a b c | 4.5 | 2 cores | LP_NUM_THREADS unset");
  EXPECT_EQ(app::calibrationKey("r", "v", 16, "4"), "r | v | 16 cores | LP_NUM_THREADS 4");
}

TEST(PipelineChoice, TheFitRecoversCostsAndKeepsThemNonNegative) {
  const std::vector<double> g{2000, 16000, 2000, 16000}, px{76800, 76800, 480000, 480000};
  std::vector<double> t;
  for (std::size_t i = 0; i < g.size(); ++i) t.push_back(3.0 + 1.5 * g[i] * 1e-3 + 40.0 * px[i] * 1e-6);
  const app::PathCost c = app::fitPathCost(g, px, t);
  EXPECT_NEAR(c.fixedMs, 3.0, 1e-9);
  EXPECT_NEAR(c.glyphUs, 1.5, 1e-9);
  EXPECT_NEAR(c.megapixelMs, 40.0, 1e-9);
  // Frames that would fit a negative fixed cost: it is left out, and the
  // others fit what remains.
  const std::vector<double> noisy{1.0, 20.0, 15.0, 36.0};
  const app::PathCost n = app::fitPathCost(g, px, noisy);
  EXPECT_GE(n.fixedMs, 0.0);
  EXPECT_GE(n.glyphUs, 0.0);
  EXPECT_GE(n.megapixelMs, 0.0);
  EXPECT_GT(n.predictMs(16000, 480000), n.predictMs(2000, 76800));
  EXPECT_THROW(app::fitPathCost({1, 2}, {1, 2}, {1, 2}), std::invalid_argument);
}
