#include "render/color_scalar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

namespace tg::render {

bool colorIsScalar(ColorMode m) { return m != ColorMode::DEC && m != ColorMode::DecFA && m != ColorMode::Sign; }

bool colorIsSigned(ColorMode m) {
  return m == ColorMode::Pressure || m == ColorMode::S1 || m == ColorMode::S2 || m == ColorMode::S3 ||
         m == ColorMode::Trace;
}

bool colorHasTensorUnits(ColorMode m) {
  switch (m) {
    case ColorMode::DEC:
    case ColorMode::DecFA:
    case ColorMode::FA:
    case ColorMode::CL:
    case ColorMode::CP:
    case ColorMode::Array: return false;
    default: return true;
  }
}

Colormap defaultColormap(ColorMode m) { return colorIsSigned(m) ? Colormap::Diverging : Colormap::Viridis; }

const char* colorQuantityName(ColorMode m) {
  switch (m) {
    case ColorMode::DEC: return "DEC: principal eigenvector e1";
    case ColorMode::DecFA: return "DEC x FA: e1 weighted by FA";
    case ColorMode::FA: return "FA (fractional anisotropy)";
    case ColorMode::MD: return "MD, mean eigenvalue";
    case ColorMode::CL: return "cl (Westin linear)";
    case ColorMode::CP: return "cp (Westin planar)";
    case ColorMode::Sign: return "normal stress";
    case ColorMode::VonMises: return "von Mises stress";
    case ColorMode::Tresca: return "Tresca stress s1 - s3";
    case ColorMode::Pressure: return "pressure -trace/3";
    case ColorMode::S1: return "s1, largest principal value";
    case ColorMode::S2: return "s2, middle principal value";
    case ColorMode::S3: return "s3, smallest principal value";
    case ColorMode::Trace: return "trace";
    case ColorMode::Array: return "array";
  }
  return "";
}

const char* colormapName(Colormap m) {
  switch (m) {
    case Colormap::Gray: return "gray";
    case Colormap::Viridis: return "viridis";
    case Colormap::Diverging: return "diverging";
  }
  return "";
}

double colorScalar(ColorMode m, const double l[3], double fa) {
  const double tr = l[0] + l[1] + l[2];
  switch (m) {
    case ColorMode::FA: return fa;
    case ColorMode::CL:
    case ColorMode::CP: {
      // Westin's measures, 0 for a non-positive trace (westinLinearPlanar).
      if (!(tr > 1e-12 * std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]))) return 0.0;
      return m == ColorMode::CL ? (l[0] - l[1]) / tr : 2.0 * (l[1] - l[2]) / tr;
    }
    case ColorMode::MD: return tr / 3.0;
    case ColorMode::VonMises: {
      const double a = l[0] - l[1], b = l[1] - l[2], c = l[2] - l[0];
      return std::sqrt(0.5 * (a * a + b * b + c * c));
    }
    case ColorMode::Tresca: return l[0] - l[2];
    case ColorMode::Pressure: return -tr / 3.0;
    case ColorMode::S1: return l[0];
    case ColorMode::S2: return l[1];
    case ColorMode::S3: return l[2];
    case ColorMode::Trace: return tr;
    default: return 0.0;
  }
}

ColorRanges::ColorRanges() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  of.fill(glm::dvec2(inf, -inf));
}

void ColorRanges::add(const ColorRanges& o) {
  for (std::size_t k = 0; k < of.size(); ++k)
    of[k] = glm::dvec2(std::min(of[k].x, o.of[k].x), std::max(of[k].y, o.of[k].y));
  maxAbsEigenvalue = std::max(maxAbsEigenvalue, o.maxAbsEigenvalue);
}

namespace {

ColorRanges rangesOf(std::span<const tensor::GlyphRecord> glyphs) {
  ColorRanges r;
  constexpr ColorMode kDerived[] = {ColorMode::FA,       ColorMode::MD,       ColorMode::CL, ColorMode::CP,
                                    ColorMode::VonMises, ColorMode::Tresca,   ColorMode::Pressure,
                                    ColorMode::S1,       ColorMode::S2,       ColorMode::S3, ColorMode::Trace};
  for (const tensor::GlyphRecord& g : glyphs) {
    const double l[3] = {g.eigenvalues[0], g.eigenvalues[1], g.eigenvalues[2]};
    const double m = std::max(std::abs(l[0]), std::abs(l[2]));
    if (!(m > 0.0)) continue;
    r.maxAbsEigenvalue = std::max(r.maxAbsEigenvalue, m);
    for (const ColorMode c : kDerived) {
      const double v = colorScalar(c, l, g.fa);
      glm::dvec2& span = r.of[std::size_t(c)];
      span = glm::dvec2(std::min(span.x, v), std::max(span.y, v));
    }
  }
  return r;
}

}  // namespace

// On up to 16 threads: at upload, every glyph's eleven scalars.
ColorRanges colorRanges(std::span<const tensor::GlyphRecord> glyphs) {
  constexpr std::size_t kPerThread = std::size_t(1) << 16;
  const std::size_t n = glyphs.size();
  const std::size_t threads =
      std::clamp<std::size_t>(std::min<std::size_t>(n / kPerThread, std::thread::hardware_concurrency()), 1, 16);
  if (threads == 1) return rangesOf(glyphs);
  std::vector<ColorRanges> parts(threads);
  {
    std::vector<std::jthread> pool;
    for (std::size_t t = 0; t < threads; ++t)
      pool.emplace_back([&, t] {
        const std::size_t lo = n * t / threads, hi = n * (t + 1) / threads;
        parts[t] = rangesOf(glyphs.subspan(lo, hi - lo));
      });
  }
  for (std::size_t t = 1; t < threads; ++t) parts[0].add(parts[t]);
  return parts[0];
}

ColorRanges colorRanges(const tensor::GlyphSet& set) {
  ColorRanges r = colorRanges(std::span(set.glyphs.data(), set.glyphs.size()));
  r.of[std::size_t(ColorMode::MD)] = glm::dvec2(set.mdMin, set.mdMax);
  r.maxAbsEigenvalue = set.maxAbsEigenvalue;
  return r;
}

glm::dvec2 finiteRange(std::span<const float> values) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  glm::dvec2 r(inf, -inf);
  for (const float v : values)
    if (std::isfinite(v)) r = glm::dvec2(std::min(r.x, double(v)), std::max(r.y, double(v)));
  return r;
}

std::vector<float> scalarsByRecord(std::span<const tensor::GlyphRecord> glyphs, std::span<const float> byInput) {
  std::vector<float> out(glyphs.size());
  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    if (glyphs[i].id >= byInput.size())
      throw std::invalid_argument("scalarsByRecord: " + std::to_string(byInput.size()) +
                                  " values, but the tensors' input indices reach " + std::to_string(glyphs[i].id));
    out[i] = byInput[glyphs[i].id];
  }
  return out;
}

glm::dvec2 resolveColorWindow(const FrameParams& p, glm::dvec2 range, double maxAbsEigenvalue) {
  if (p.color == ColorMode::Sign) {
    const double m = p.colorWindow ? std::max(std::abs(p.colorWindow->x), std::abs(p.colorWindow->y)) : maxAbsEigenvalue;
    return glm::dvec2(-m, m);
  }
  if (p.colorWindow) return *p.colorWindow;
  if (p.color == ColorMode::FA || p.color == ColorMode::CL || p.color == ColorMode::CP) return glm::dvec2(0.0, 1.0);
  if (!(range.x <= range.y)) return glm::dvec2(0.0);
  if (resolveColormap(p) == Colormap::Diverging) {
    const double m = std::max(std::abs(range.x), std::abs(range.y));
    return glm::dvec2(-m, m);
  }
  return range;
}

}  // namespace tg::render
