#pragma once
// The measurement behind `--pipeline auto` (app/scale/pipeline_choice.h):
// frames of random fields (synth random, framed as `bench scale` frames
// them) on every glyph path, for each cost class at two glyph counts and two
// frame sizes, fitted per path and class; and the cache file that keeps one
// such table per GL renderer, driver and core count, so that a machine
// measures once.
#include <string>
#include <vector>

#include "app/scale/pipeline_choice.h"
#include "gl/loader.h"
#include "gl/shader_library.h"

namespace tg::app {

struct CalibrationPlan {
  std::vector<std::size_t> glyphs{2000, 16000};
  std::vector<std::pair<int, int>> sizes{{320, 240}, {800, 600}};
  int frames = 2;  // timed, after one warm-up; the fastest is kept
  // calibrationGlyphs: on a device that draws the largest count in less
  // than growUntilMs, every count is multiplied by 8 until it does not, or
  // the largest would pass maxGlyphs.
  double growUntilMs = 10.0;
  std::size_t maxGlyphs = std::size_t(1) << 21;
};

// The plan's glyph counts for this device: a GPU draws 16,000 glyphs in
// about a millisecond, where fixed costs hide the per-glyph ones a fit needs,
// so the counts grow until the raster path's ellipsoid frame at the largest
// count and size takes growUntilMs (llvmpipe keeps the plan's).
std::vector<std::size_t> calibrationGlyphs(const gl::Api& gl, const gl::ShaderLibrary& lib, const CalibrationPlan& plan);

// Every path and class of the plan on the current context, fitted.
PathCalibration calibratePaths(const gl::Api& gl, const gl::ShaderLibrary& lib, const std::string& key,
                               const CalibrationPlan& plan = {});

// Least squares for fixed, per-glyph and per-pixel costs with none negative
// (the subset of terms whose fit is non-negative and leaves the least
// residual): frames[i] ms at glyphs[i], pixels[i]. Needs 3 points or more.
PathCost fitPathCost(const std::vector<double>& glyphs, const std::vector<double>& pixels,
                     const std::vector<double>& frameMs);

// The cache's key for the current context (calibrationKey): its GL_RENDERER
// and GL_VERSION, this machine's cores and LP_NUM_THREADS.
std::string currentCalibrationKey(const gl::Api& gl);

// The cache file: $TG_CACHE_DIR/pipelines.tsv, else
// $XDG_CACHE_HOME/tensorglyph/pipelines.tsv, else
// $HOME/.cache/tensorglyph/pipelines.tsv; "" when none of those is set.
std::string calibrationCachePath();

struct CachedCalibration {
  PathCalibration cal;
  std::string file;       // where it is kept ("" when not kept)
  bool measured = false;  // measured by this call
  double measuredMs = 0;  // how long that took
  // What the user should hear, one line: what was measured and where it is
  // kept, or why a cache could not be read or written. Empty when the
  // calibration came from the cache.
  std::string said;
};
// The calibration for `key` from the cache; else measured now and written
// into it through a temporary file, other keys' rows kept. A cache that
// cannot be read, or lacks one of this key's rows, is measured over and
// rewritten. Concurrent callers take turns on a lock file beside the cache
// (waiting at most 60 s), so a machine measures once and no caller's rows
// are lost.
CachedCalibration calibrationFor(const gl::Api& gl, const gl::ShaderLibrary& lib, const std::string& key);
// Whether `cal` holds every path's row for every cost class.
bool calibrationComplete(const PathCalibration& cal);

}  // namespace tg::app
