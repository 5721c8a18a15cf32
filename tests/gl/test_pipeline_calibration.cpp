// Tier 3: --pipeline auto's measurement on this context (llvmpipe in CI)
// and its cache (app/scale/pipeline_calibration.h). The times themselves
// are the machine's; what is checked is that every path and class is
// measured into a usable table, and that the cache is kept, reused and
// rebuilt when it cannot be read.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/scale/pipeline_calibration.h"
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
  ASSERT_EQ(cal.rows.size(), 4u);
  for (const char* path : {"raster", "cpu"})
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

TEST_F(PipelineCalibration, TheCacheIsKeptReusedAndRebuiltWhenUnreadable) {
  ctx_->makeCurrent();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("tg-calibration-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  ::setenv("TG_CACHE_DIR", dir.c_str(), 1);
  const std::string file = (dir / "pipelines.tsv").string();
  EXPECT_EQ(app::calibrationCachePath(), file);
  int told = 0;
  const auto tell = [&](const std::string& f) {
    ++told;
    EXPECT_EQ(f, file);
  };
  const app::CachedCalibration first = app::calibrationFor(ctx_->api(), *lib_, "renderer A", tell);
  EXPECT_TRUE(first.measured);
  EXPECT_EQ(first.warning, "");
  EXPECT_EQ(told, 1);
  ASSERT_TRUE(std::filesystem::exists(file));
  const app::CachedCalibration again = app::calibrationFor(ctx_->api(), *lib_, "renderer A", tell);
  EXPECT_FALSE(again.measured);
  EXPECT_EQ(told, 1);
  ASSERT_EQ(again.cal.rows.size(), 4u);
  EXPECT_DOUBLE_EQ(again.cal.rows[3].cost.glyphUs, first.cal.rows[3].cost.glyphUs);
  // A truncated cache: one line names the file and the problem, and it is
  // measured and written whole again.
  {
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    std::ofstream(file, std::ios::trunc) << text.substr(0, text.size() - 7);
  }
  const app::CachedCalibration rebuilt = app::calibrationFor(ctx_->api(), *lib_, "renderer A", tell);
  EXPECT_TRUE(rebuilt.measured);
  EXPECT_NE(rebuilt.warning.find(file + ":1: does not end with a line break"), std::string::npos) << rebuilt.warning;
  EXPECT_EQ(told, 2);
  EXPECT_FALSE(app::calibrationFor(ctx_->api(), *lib_, "renderer A", tell).measured);
  ::unsetenv("TG_CACHE_DIR");
  std::filesystem::remove_all(dir);
}
