#include "tensor/glyph_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/vector_relational.hpp>

namespace tg::tensor {
namespace {

constexpr std::size_t kSampleMax = 65536;

double magnitudeOf(const GlyphRecord& g) {
  return std::max(std::abs(double(g.eigenvalues[0])), std::abs(double(g.eigenvalues[2])));
}

std::string format(const char* fmt, auto... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

}  // namespace

std::optional<Magnitude> magnitudeNamed(const std::string& name) {
  if (name == "linear") return Magnitude::Linear;
  if (name == "log") return Magnitude::Log;
  if (name == "shape") return Magnitude::Shape;
  return std::nullopt;
}

const char* magnitudeName(Magnitude m) {
  switch (m) {
    case Magnitude::Linear: return "linear";
    case Magnitude::Log: return "log";
    case Magnitude::Shape: return "shape";
  }
  return "linear";
}

double mappedMagnitude(const SizeMapping& s, double m) {
  if (!(m > 0.0)) return 0.0;
  switch (s.magnitude) {
    case Magnitude::Linear: return m;
    case Magnitude::Log: return s.lambda0 * std::log1p(m / s.lambda0);
    case Magnitude::Shape: return s.lambda0;
  }
  return m;
}

double glyphFactor(double scale, const SizeMapping& s, double m) {
  double k = scale;
  if (!(m > 0.0)) return k;
  if (s.magnitude != Magnitude::Linear) k *= mappedMagnitude(s, m) / m;
  if (s.maxRadiusWC > 0.0 && k * m > s.maxRadiusWC) k = s.maxRadiusWC / m;
  return k;
}

glm::dvec3 glyphAxes(const GlyphRecord& g, double scale, const SizeMapping& s) {
  return ellipsoidAxes(g, glyphFactor(scale, s, magnitudeOf(g)));
}

MagnitudeSample magnitudeSample(const FieldStats& stats, double spacing, std::string from) {
  MagnitudeSample s;
  s.sorted = stats.sortedMagnitudes();
  s.maxAbs = stats.maxAbs;
  s.spacing = spacing;
  s.from = std::move(from);
  return s;
}

MagnitudeSample sampleMagnitudes(const GlyphSet& set, double spacing) {
  return magnitudeSample(fieldStats(set), spacing);
}

double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const auto k = std::size_t(std::clamp(q, 0.0, 1.0) * double(sorted.size() - 1) + 0.5);
  return sorted[std::min(k, sorted.size() - 1)];
}

ResolvedScale resolveScale(const ScaleParams& p, const MagnitudeSample& sample) {
  ResolvedScale r;
  SizeMapping& map = r.mapping;
  map.magnitude = p.magnitude;
  // λ0: the median of the non-zero magnitudes, so that the typical glyph sits
  // at the knee of the log mapping.
  // Percentiles are of the glyphs that have a size: zero tensors draw
  // nothing, and a volume that is mostly background (zeros outside the
  // brain) must not be sized by them.
  const std::vector<double> sized(std::upper_bound(sample.sorted.begin(), sample.sorted.end(), 0.0),
                                  sample.sorted.end());
  const double median = sized.empty() ? 1.0 : sized[sized.size() / 2];
  map.lambda0 = p.lambda0.value_or(median);
  const double spacing = sample.spacing;
  const bool haveSpacing = spacing > 0.0 && std::isfinite(spacing);
  std::string how;
  switch (p.mode) {
    case ScaleMode::Absolute:
      // ParaView's ScaleFactor (its glyph source has radius 0.5): the
      // diameter per eigenvalue unit, so the semi-axis is half of it.
      r.scale = 0.5 * p.factor;
      how = format("absolute: %g world units of diameter per eigenvalue unit (ParaView's ScaleFactor)", p.factor);
      break;
    case ScaleMode::Max:
    case ScaleMode::Spacing: {
      const bool max = p.mode == ScaleMode::Max;
      const double m = max ? sample.maxAbs : quantile(sized, p.percentile);
      const double f = mappedMagnitude(map, m);
      r.scale = haveSpacing && f > 0.0 ? p.factor * 0.5 * spacing / f : p.factor;
      how = max ? format("max: the largest glyph (|eigenvalue| %g) is %g sample spacings across", m, p.factor)
                : format("spacing: the glyph at the %g%% of non-zero sizes (|eigenvalue| %g) is %g sample spacings across",
                         100.0 * p.percentile, m, p.factor);
      if (!haveSpacing || !(f > 0.0)) how += " (undefined here: scale 1)";
      break;
    }
  }
  const double clamp = p.clampSpacings.value_or(p.mode == ScaleMode::Absolute ? 0.0 : ScaleParams::kDefaultClamp);
  map.maxRadiusWC = clamp > 0.0 && haveSpacing ? 0.5 * clamp * spacing : 0.0;
  std::size_t clamped = 0;
  const SizeMapping unclamped{map.magnitude, map.lambda0, 0.0};
  for (double m : sized) clamped += glyphFactor(r.scale, map, m) != glyphFactor(r.scale, unclamped, m);
  r.clampedFraction = sized.empty() ? 0.0 : double(clamped) / double(sized.size());
  r.typicalRadiusWC = glyphRadiusWC(r.scale, map, quantile(sized, p.percentile));
  r.why = format("scale %.6g (%s), sample spacing %g; magnitude %s", r.scale, how.c_str(), spacing,
                 magnitudeName(map.magnitude));
  if (map.magnitude != Magnitude::Linear)
    r.why += format(" (lambda0 %g%s)", map.lambda0, p.lambda0 ? "" : ", the median |eigenvalue|");
  r.why += map.maxRadiusWC > 0.0
               ? format("; clamp %g sample spacings across (%.1f%% of glyphs shrunk)", clamp, 100.0 * r.clampedFraction)
               : std::string("; no clamp");
  if (!sample.from.empty()) r.why += "; ranges from " + sample.from;
  return r;
}

double defaultScale(const GlyphSet& set, double spacing) {
  return resolveScale(ScaleParams{}, sampleMagnitudes(set, spacing)).scale;
}

BoxWC glyphBoxWC(const GlyphSet& set, double scale, const SizeMapping& s) {
  const double pad = kGlyphReach * maxGlyphRadiusWC(set, scale, s);
  return {set.boundsMinWC - pad, set.boundsMaxWC + pad};
}

FramingBox framingBox(const GlyphSet& set, bool scattered, double padWC) {
  FramingBox b;
  b.lo = set.boundsMinWC;
  b.hi = set.boundsMaxWC;
  b.why = scattered ? "the sample points' bounds" : "the grid samples' bounds";
  const bool someZero = set.sizedBoundsMinWC != set.boundsMinWC || set.sizedBoundsMaxWC != set.boundsMaxWC;
  const bool framesZero = !(someZero && glm::all(glm::lessThanEqual(set.sizedBoundsMinWC, set.sizedBoundsMaxWC)));
  if (!framesZero) {
    b.lo = set.sizedBoundsMinWC;
    b.hi = set.sizedBoundsMaxWC;
    b.why = scattered ? "the bounds of the sample points whose tensors are not zero"
                      : "the bounds of the grid samples whose tensors are not zero";
  }
  const std::size_t n = set.glyphs.size();
  if (scattered && n >= 200) {
    const std::size_t step = std::max<std::size_t>(1, (n + kSampleMax - 1) / kSampleMax);
    glm::dvec3 plo, phi;
    bool outliers = false;
    std::vector<double> v;
    v.reserve(n / step + 1);
    for (int a = 0; a < 3; ++a) {
      v.clear();
      for (std::size_t i = 0; i < n; i += step) {
        const GlyphRecord& g = set.glyphs[i];
        if (!framesZero && g.eigenvalues[0] == 0.0f && g.eigenvalues[2] == 0.0f) continue;
        v.push_back(g.posWC[a]);
      }
      if (v.empty()) {  // the sample met only zero tensors: keep the bounds
        outliers = false;
        break;
      }
      std::sort(v.begin(), v.end());
      plo[a] = quantile(v, 0.005);
      phi[a] = quantile(v, 0.995);
      const double full = b.hi[a] - b.lo[a], robust = phi[a] - plo[a];
      outliers = outliers || full > kOutlierSpread * robust + 1e-12 * (std::abs(b.lo[a]) + std::abs(b.hi[a]));
    }
    if (outliers) {
      b.lo = plo;
      b.hi = phi;
      b.why = "the 0.5..99.5 percentile box of the sample points (their bounds are more than 1.25 times wider)";
    }
  }
  b.lo -= padWC;
  b.hi += padWC;
  b.why += format(", grown by a typical glyph's radius %g", padWC);
  return b;
}

}  // namespace tg::tensor
