#include "ref/image_diff.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace tg::ref {
namespace {

ErrorSummary summarise(std::vector<double>& v) {
  ErrorSummary s;
  s.count = v.size();
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.median = v[v.size() / 2];
  s.p99 = v[std::min(v.size() - 1, std::size_t(std::ceil(0.99 * double(v.size()))) - 1)];
  s.max = v.back();
  return s;
}

}  // namespace

ImageDiff diffImages(const render::FrameImage& g, const RefImage& r, const render::Camera& cam,
                     const DiffOptions& opt) {
  const int w = r.width, h = r.height;
  const std::size_t n = std::size_t(w) * h;
  if (g.width != w || g.height != h || g.id.size() != n || g.depth.size() != n || g.normalWC.size() != 3 * n ||
      g.rgba.size() != 4 * n)
    throw std::invalid_argument("diffImages: the GPU frame needs every channel at the reference's size");
  const bool ortho = cam.desc.projection == render::Projection::Orthographic;
  auto unit = [&](std::uint32_t id, double refDepth) {
    if (opt.depthUnit) return opt.depthUnit(id, refDepth);
    return ortho ? cam.farVC - cam.nearVC : refDepth;
  };
  auto onSilhouette = [&](int i, int j) {
    const std::uint32_t id = r.id[std::size_t(j) * w + i];
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int x = std::clamp(i + di, 0, w - 1), y = std::clamp(j + dj, 0, h - 1);
        if (r.id[std::size_t(y) * w + x] != id) return true;
      }
    return false;
  };
  ImageDiff d;
  std::vector<double> depthErr, normalErr;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const std::size_t p = std::size_t(j) * w + i;
      const bool rc = r.id[p] != kNoGlyph, gc = g.id[p] != kNoGlyph;
      for (int k = 0; k < 4; ++k) d.nonFinite += !std::isfinite(g.rgba[4 * p + k]);
      for (int k = 0; k < 3; ++k) d.nonFinite += !std::isfinite(g.normalWC[3 * p + k]);
      if (gc && !std::isfinite(g.depth[p])) ++d.nonFinite;
      d.refCovered += rc;
      d.gpuCovered += gc;
      if (rc != gc) {
        ++d.coverageMismatch;
        if (!onSilhouette(i, j)) ++d.interiorMismatch;
        continue;
      }
      if (!rc) continue;
      const bool silhouette = onSilhouette(i, j);
      if (g.id[p] != r.id[p]) {
        const bool tie = std::abs(g.depth[p] - r.depth[p]) <= 1e-6 * r.depth[p];
        if (!silhouette && !tie) ++d.idMismatch;
        continue;
      }
      if (silhouette && !opt.includeSilhouettes) continue;
      depthErr.push_back(std::abs(g.depth[p] - r.depth[p]) / unit(r.id[p], r.depth[p]));
      const glm::dvec3 nG(g.normalWC[3 * p], g.normalWC[3 * p + 1], g.normalWC[3 * p + 2]);
      const double cosA = std::clamp(glm::dot(glm::normalize(nG), r.normalWC[p]), -1.0, 1.0);
      normalErr.push_back(glm::degrees(std::acos(cosA)));
    }
  d.depth = summarise(depthErr);
  d.normalDeg = summarise(normalErr);
  return d;
}

}  // namespace tg::ref
