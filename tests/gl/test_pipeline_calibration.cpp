// Tier 3: --pipeline auto's measurement on this context (llvmpipe in CI)
// and its cache (app/scale/pipeline_calibration.h). The times themselves
// are the machine's; what is checked is that every path and class is
// measured into a usable table, and that the cache is kept, reused and
// rebuilt when it cannot be read.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>

#include "app/scale/pipeline_calibration.h"
#include "render/glyph_path.h"
#include "render_fixture.h"

using namespace tg;
using test::GlFixture;

class PipelineCalibration : public GlFixture {};

TEST_F(PipelineCalibration, EveryPathAndClassIsMeasured) {
  ctx_->makeCurrent();
  app::CalibrationPlan plan;
  plan.glyphs = {200, 1600};
  plan.sizes = {{64, 48}, {160, 120}};
  plan.frames = 1;
  const app::PathCalibration cal = app::calibratePaths(ctx_->api(), *lib_, "key", plan);
  EXPECT_EQ(cal.key, "key");
  ASSERT_EQ(cal.rows.size(), 2 * std::size(render::kGlyphPathNames));
  for (const std::string_view path : render::kGlyphPathNames)
    for (const app::CostClass c : {app::CostClass::ClosedForm, app::CostClass::March}) {
      const app::PathCost* cost = cal.cost(path, c);
      ASSERT_NE(cost, nullptr) << path;
      for (const double v : {cost->fixedMs, cost->glyphUs, cost->megapixelMs}) {
        EXPECT_TRUE(std::isfinite(v)) << path;
        EXPECT_GE(v, 0.0) << path;
      }
      // A frame takes time: the fit of real frames predicts some.
      EXPECT_GT(cost->predictMs(1600, 160 * 120), 0.0) << path;
    }
}

// Counts grow by 8 while the largest draws faster than growUntilMs, up to
// maxGlyphs: a bound no frame meets grows them to the cap, one every frame
// meets keeps them.
TEST_F(PipelineCalibration, TheCountsGrowOnlyWhileFramesAreFasterThanAsked) {
  ctx_->makeCurrent();
  app::CalibrationPlan plan;
  plan.glyphs = {10, 20};
  plan.sizes = {{16, 16}};
  plan.frames = 1;
  plan.maxGlyphs = 1300;
  plan.growUntilMs = 1e9;
  EXPECT_EQ(app::calibrationGlyphs(ctx_->api(), *lib_, plan), (std::vector<std::size_t>{640, 1280}));
  plan.growUntilMs = 1e-9;
  EXPECT_EQ(app::calibrationGlyphs(ctx_->api(), *lib_, plan), (std::vector<std::size_t>{10, 20}));
  plan.growUntilMs = 0;
  EXPECT_EQ(app::calibrationGlyphs(ctx_->api(), *lib_, plan), (std::vector<std::size_t>{10, 20}));
}

TEST_F(PipelineCalibration, TheCacheIsKeptReusedAndRebuiltWhenUnreadableOrIncomplete) {
  ctx_->makeCurrent();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("tg-calibration-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  ::setenv("TG_CACHE_DIR", dir.c_str(), 1);
  const std::string file = (dir / "pipelines.tsv").string();
  EXPECT_EQ(app::calibrationCachePath(), file);
  const app::CachedCalibration first = app::calibrationFor(ctx_->api(), *lib_, "renderer A");
  EXPECT_TRUE(first.measured);
  EXPECT_NE(first.said.find("measured the glyph paths on this renderer in "), std::string::npos) << first.said;
  // llvmpipe draws 16,000 glyphs at 800x600 slower than the growth bound: the plan's counts.
  EXPECT_NE(first.said.find(" s (2000 and 16000 glyphs), kept in "), std::string::npos) << first.said;
  EXPECT_NE(first.said.find(", kept in " + file), std::string::npos) << first.said;
  ASSERT_TRUE(std::filesystem::exists(file));
  const app::CachedCalibration again = app::calibrationFor(ctx_->api(), *lib_, "renderer A");
  EXPECT_FALSE(again.measured);
  EXPECT_EQ(again.said, "");
  ASSERT_EQ(again.cal.rows.size(), 2 * std::size(render::kGlyphPathNames));
  EXPECT_DOUBLE_EQ(again.cal.rows[3].cost.glyphUs, first.cal.rows[3].cost.glyphUs);
  // Another renderer's rows are kept beside these.
  EXPECT_TRUE(app::calibrationFor(ctx_->api(), *lib_, "renderer B").measured);
  EXPECT_FALSE(app::calibrationFor(ctx_->api(), *lib_, "renderer A").measured);
  auto slurp = [&] {
    std::ifstream in(file);
    return std::string((std::istreambuf_iterator<char>(in)), {});
  };
  auto drop = [&](std::size_t chars) {
    const std::string text = slurp();
    std::ofstream(file, std::ios::trunc) << text.substr(0, text.size() - chars);
  };
  // A truncated cache, and one that lacks a row of this renderer's: named
  // in the one line said, measured again and written whole.
  drop(7);
  const std::string cut = slurp();
  const std::string lastLine = std::to_string(std::count(cut.begin(), cut.end(), '\n') + 1);
  const app::CachedCalibration rebuilt = app::calibrationFor(ctx_->api(), *lib_, "renderer A");
  EXPECT_TRUE(rebuilt.measured);
  EXPECT_EQ(rebuilt.said.rfind(file + ":" + lastLine + ": does not end with a line break (a truncated write?); measured the glyph paths", 0), 0u)
      << rebuilt.said;
  EXPECT_FALSE(app::calibrationFor(ctx_->api(), *lib_, "renderer A").measured);
  const std::string whole = slurp();
  const std::size_t lastRow = whole.rfind('\n', whole.size() - 2) + 1;
  std::ofstream(file, std::ios::trunc) << whole.substr(0, lastRow);
  const std::string lastKey = whole.substr(lastRow, whole.find('\t', lastRow) - lastRow);
  const app::CachedCalibration refilled = app::calibrationFor(ctx_->api(), *lib_, lastKey);
  EXPECT_TRUE(refilled.measured);
  EXPECT_EQ(refilled.said.rfind(file + ": this renderer's rows are incomplete; measured", 0), 0u) << refilled.said;
  EXPECT_TRUE(app::calibrationComplete(app::calibrationFor(ctx_->api(), *lib_, lastKey).cal));
  ::unsetenv("TG_CACHE_DIR");
  std::filesystem::remove_all(dir);
}
