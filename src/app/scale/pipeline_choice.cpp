#include "app/scale/pipeline_choice.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <stdexcept>

#include "render/glyph_path.h"
#include "util/strict_number.h"

namespace tg::app {
namespace {

constexpr std::string_view kHeader = "# tensorglyph --pipeline auto calibration 1";
constexpr std::string_view kColumns = "key\tpath\tclass\tfixed_ms\tglyph_us\tmegapixel_ms";
// A cache holds a few renderers; anything larger is not one of ours.
constexpr std::size_t kMaxBytes = 64 * 1024;
constexpr double kMaxCoefficient = 1e7;

std::vector<std::string_view> drawingPaths(render::GlyphKind kind, const std::vector<render::GlyphKind>& alsoDraws) {
  std::vector<std::string_view> paths;
  for (const std::string_view path : render::kGlyphPathNames) {
    bool all = render::pathDraws(path, kind);
    for (const render::GlyphKind k : alsoDraws) all = all && render::pathDraws(path, k);
    if (all) paths.push_back(path);
  }
  return paths;
}

std::string ms(double v) {
  char b[32];
  std::snprintf(b, sizeof b, v < 10.0 ? "%.1f ms" : "%.0f ms", v);
  return b;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> parts;
  for (std::size_t at = 0;;) {
    const std::size_t end = s.find(sep, at);
    parts.push_back(s.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
    if (end == std::string_view::npos) return parts;
    at = end + 1;
  }
}

}  // namespace

double PathCost::predictMs(double glyphs, double pixels) const {
  return fixedMs + glyphUs * glyphs * 1e-3 + megapixelMs * pixels * 1e-6;
}

const PathCost* PathCalibration::cost(std::string_view path, CostClass c) const {
  for (const Row& r : rows)
    if (r.path == path && r.cls == c) return &r.cost;
  return nullptr;
}

std::string calibrationKey(std::string_view renderer, std::string_view version, unsigned cores,
                           std::string_view lpNumThreads) {
  std::string key = std::string(renderer) + " | " + std::string(version) + " | " + std::to_string(cores) +
                    " cores | LP_NUM_THREADS " + (lpNumThreads.empty() ? std::string("unset") : std::string(lpNumThreads));
  for (char& c : key)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return key;
}

CostClass costClassOf(render::GlyphKind kind, double gamma) {
  // At gamma 0 the superquadric kind draws its definite glyphs by the
  // ellipsoid's closed form (render::KindDraw::Superquadric).
  return render::glyphKind(kind).draw == render::KindDraw::Superquadric && gamma > 0.0 ? CostClass::March
                                                                                       : CostClass::ClosedForm;
}

bool choiceNeedsCalibration(render::GlyphKind kind, const std::vector<render::GlyphKind>& alsoDraws) {
  return drawingPaths(kind, alsoDraws).size() > 1;
}

PathChoice choosePath(const PathCalibration* cal, render::GlyphKind kind, double gamma, double glyphs, double pixels,
                      const std::vector<render::GlyphKind>& alsoDraws) {
  const std::vector<std::string_view> paths = drawingPaths(kind, alsoDraws);
  const std::string kindName(render::glyphKind(kind).name);
  if (paths.empty()) throw std::invalid_argument("choosePath: no glyph path draws " + kindName + " glyphs and the rest asked for");
  if (paths.size() == 1) return {std::string(paths[0]), "the only path that draws " + kindName + " glyphs here"};
  if (!cal) throw std::invalid_argument("choosePath: no calibration to choose between the paths");
  const CostClass cls = costClassOf(kind, gamma);
  PathChoice best;
  double bestMs = INFINITY;
  std::string others;
  for (const std::string_view path : paths) {
    const PathCost* c = cal->cost(path, cls);
    if (!c)
      throw std::invalid_argument("choosePath: the calibration has no " + std::string(path) + " row for " +
                                  std::string(kCostClassNames[int(cls)]) + " glyphs");
    const double t = c->predictMs(glyphs, pixels);
    // Ties go to the earlier path: raster, the default.
    if (t < bestMs) {
      if (!best.path.empty()) others += (others.empty() ? "" : ", ") + best.path + " " + ms(bestMs);
      bestMs = t;
      best.path = path;
    } else {
      others += (others.empty() ? "" : ", ") + std::string(path) + " " + ms(t);
    }
  }
  char counts[96];
  std::snprintf(counts, sizeof counts, "%.0f %s glyphs, %.2f Mpixel", glyphs, std::string(kCostClassNames[int(cls)]).c_str(),
                pixels * 1e-6);
  best.why = "predicted " + ms(bestMs) + " a frame against " + others + " (" + counts + ")";
  return best;
}

std::string formatCalibrations(const std::vector<PathCalibration>& cals) {
  std::string s = std::string(kHeader) + "\n" + std::string(kColumns) + "\n";
  for (const PathCalibration& cal : cals)
    for (const PathCalibration::Row& r : cal.rows) {
      char nums[128];
      std::snprintf(nums, sizeof nums, "\t%.17g\t%.17g\t%.17g\n", r.cost.fixedMs, r.cost.glyphUs, r.cost.megapixelMs);
      s += cal.key + "\t" + r.path + "\t" + std::string(kCostClassNames[int(r.cls)]) + nums;
    }
  return s;
}

std::vector<PathCalibration> parseCalibrations(std::string_view text, const std::string& file) {
  auto fail = [&](std::size_t line, const std::string& what) -> std::runtime_error {
    return std::runtime_error(file + ":" + std::to_string(line) + ": " + what);
  };
  if (text.size() > kMaxBytes)
    throw fail(1, "holds " + std::to_string(text.size()) + " bytes; a calibration cache holds at most " +
                      std::to_string(kMaxBytes));
  if (text.substr(0, text.find('\n')) != kHeader)
    throw fail(1, "is not a tensorglyph calibration cache (its first line is not \"" + std::string(kHeader) + "\")");
  if (text.back() != '\n')
    throw fail(std::size_t(std::count(text.begin(), text.end(), '\n')) + 1,
               "does not end with a line break (a truncated write?)");
  std::vector<std::string_view> lines = split(text.substr(0, text.size() - 1), '\n');
  if (lines.size() < 2 || lines[1] != kColumns) throw fail(2, "the column line is not \"" + std::string(kColumns) + "\"");
  std::vector<PathCalibration> cals;
  for (std::size_t n = 2; n < lines.size(); ++n) {
    const std::vector<std::string_view> f = split(lines[n], '\t');
    if (f.size() != 6) throw fail(n + 1, "has " + std::to_string(f.size()) + " fields; a row has 6");
    if (f[0].empty()) throw fail(n + 1, "has no key");
    PathCalibration::Row row;
    if (std::find(std::begin(render::kGlyphPathNames), std::end(render::kGlyphPathNames), f[1]) ==
        std::end(render::kGlyphPathNames))
      throw fail(n + 1, "unknown glyph path \"" + std::string(f[1]) + "\"");
    row.path = f[1];
    const auto cls = std::find(std::begin(kCostClassNames), std::end(kCostClassNames), f[2]);
    if (cls == std::end(kCostClassNames)) throw fail(n + 1, "unknown class \"" + std::string(f[2]) + "\"");
    row.cls = CostClass(cls - std::begin(kCostClassNames));
    double* out[3] = {&row.cost.fixedMs, &row.cost.glyphUs, &row.cost.megapixelMs};
    for (int k = 0; k < 3; ++k) {
      const std::optional<double> v = util::parseFinite(f[3 + k]);
      if (!v || !(*v >= 0.0 && *v <= kMaxCoefficient))
        throw fail(n + 1, "field " + std::to_string(4 + k) + " \"" + std::string(f[3 + k]) +
                              "\" is not a number in [0, 1e7]");
      *out[k] = *v;
    }
    auto at = std::find_if(cals.begin(), cals.end(), [&](const PathCalibration& c) { return c.key == f[0]; });
    if (at == cals.end()) {
      cals.push_back({std::string(f[0]), {}});
      at = cals.end() - 1;
    }
    if (at->cost(row.path, row.cls)) throw fail(n + 1, "repeats the " + row.path + " " + std::string(f[2]) + " row of its key");
    at->rows.push_back(std::move(row));
  }
  return cals;
}

}  // namespace tg::app
