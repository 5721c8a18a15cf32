#pragma once
// `--pipeline auto`: which glyph path (render/glyph_path.h) draws a scene
// fastest on this GL implementation, predicted from a short measurement of
// every path (app/scale/pipeline_calibration.h) that a cache file keeps per
// renderer, driver and core count. GL-free: given the table, the choice is
// deterministic, and the table's text is read strictly (it is a file).
#include <string>
#include <string_view>
#include <vector>

#include "render/glyph_kind.h"

namespace tg::app {

// What a glyph costs a path: a closed form (ellipsoids, and every glyph of
// a superquadric frame at gamma 0) or the Newton march.
enum class CostClass { ClosedForm, March };
inline constexpr std::string_view kCostClassNames[] = {"closed-form", "march"};

// One path's frame time for one cost class, least-squares fitted to the
// calibration's frames: fixedMs + glyphUs * glyphs / 1e3 + megapixelMs * pixels / 1e6.
struct PathCost {
  double fixedMs = 0, glyphUs = 0, megapixelMs = 0;
  double predictMs(double glyphs, double pixels) const;
};

struct PathCalibration {
  struct Row {
    std::string path;  // render::kGlyphPathNames
    CostClass cls;
    PathCost cost;
  };
  std::string key;  // calibrationKey
  std::vector<Row> rows;
  const PathCost* cost(std::string_view path, CostClass c) const;
};

// The cache's key: GL_RENDERER, GL_VERSION (the driver), the cores and
// LP_NUM_THREADS (llvmpipe's own threads), tabs and line breaks made spaces.
std::string calibrationKey(std::string_view renderer, std::string_view version, unsigned cores,
                           std::string_view lpNumThreads);

CostClass costClassOf(render::GlyphKind kind, double gamma);

struct PathChoice {
  std::string path;
  std::string why;  // one line for --verbose
};
// The path for `glyphs` glyphs of `kind` at `gamma` in a frame of `pixels`:
// of the paths that draw `kind` and every kind in `alsoDraws`, the one
// `cal` predicts fastest; a lone such path needs no calibration. Throws
// std::invalid_argument when no path draws them all, or when two paths
// compete and `cal` lacks one of their rows.
PathChoice choosePath(const PathCalibration* cal, render::GlyphKind kind, double gamma, double glyphs, double pixels,
                      const std::vector<render::GlyphKind>& alsoDraws = {});
// Whether choosePath has more than one path to pick from (a calibration is needed).
bool choiceNeedsCalibration(render::GlyphKind kind, const std::vector<render::GlyphKind>& alsoDraws);

// The cache file's text, a header line and then a tab-separated row per key,
// path and class; parseCalibrations reads exactly that back, and throws
// std::runtime_error "FILE:LINE: problem" for anything else.
std::string formatCalibrations(const std::vector<PathCalibration>& cals);
std::vector<PathCalibration> parseCalibrations(std::string_view text, const std::string& file);

}  // namespace tg::app
