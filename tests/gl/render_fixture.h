#pragma once
// Tier 3 helpers: render on a real GL context and compare with the CPU reference.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "gl/backends.h"
#include "gl/shader_library.h"
#include "ref/ellipsoid_ref.h"
#include "ref/superquadric_ref.h"
#include "data-synthetic/generators.h"
#include "render/renderer.h"

namespace tg::test {

struct Comparison {
  std::size_t refCovered = 0, gpuCovered = 0;
  std::size_t coverageMismatch = 0, interiorMismatch = 0;  // interior: not on a reference silhouette
  std::size_t idMismatch = 0;
  double maxRelDepthError = 0, maxNormalErrorDeg = 0, medianNormalErrorDeg = 0;
  std::size_t nonFinite = 0;
};

// Depth errors are relative to the depth for perspective (float keeps
// relative precision there) and to the depth range for orthographic
// projection, whose depth buffer is linear.
inline Comparison compare(const render::FrameImage& g, const ref::RefImage& r, const render::Camera& cam) {
  const bool ortho = cam.desc.projection == render::Projection::Orthographic;
  Comparison c;
  const int w = r.width, h = r.height;
  auto covered = [&](int i, int j) { return r.id[std::size_t(j) * w + i] != ref::kNoGlyph; };
  // A pixel whose 3x3 neighbourhood holds another id (or none) sits on an
  // edge, where float and double may round the other way.
  auto onEdge = [&](int i, int j) {
    const std::uint32_t id = r.id[std::size_t(j) * w + i];
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int x = std::clamp(i + di, 0, w - 1), y = std::clamp(j + dj, 0, h - 1);
        if (r.id[std::size_t(y) * w + x] != id) return true;
      }
    return false;
  };
  std::vector<double> normalErr;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const std::size_t p = std::size_t(j) * w + i;
      const bool rc = covered(i, j), gc = g.id[p] != ref::kNoGlyph;
      for (int k = 0; k < 4; ++k) c.nonFinite += !std::isfinite(g.rgba[4 * p + k]);
      for (int k = 0; k < 3; ++k) c.nonFinite += !std::isfinite(g.normalWC[3 * p + k]);
      if (gc && !std::isfinite(g.depth[p])) ++c.nonFinite;
      c.refCovered += rc;
      c.gpuCovered += gc;
      if (rc != gc) {
        ++c.coverageMismatch;
        if (!onEdge(i, j)) ++c.interiorMismatch;
        continue;
      }
      if (!rc) continue;
      if (g.id[p] != r.id[p]) {
        if (!onEdge(i, j)) ++c.idMismatch;
        continue;
      }
      if (onEdge(i, j)) continue;
      c.maxRelDepthError = std::max(c.maxRelDepthError, std::abs(g.depth[p] - r.depth[p]) / (ortho ? cam.farVC - cam.nearVC : r.depth[p]));
      const glm::dvec3 n(g.normalWC[3 * p], g.normalWC[3 * p + 1], g.normalWC[3 * p + 2]);
      const double cosA = std::clamp(glm::dot(glm::normalize(n), r.normalWC[p]), -1.0, 1.0);
      normalErr.push_back(glm::degrees(std::acos(cosA)));
    }
  if (!normalErr.empty()) {
    std::sort(normalErr.begin(), normalErr.end());
    c.maxNormalErrorDeg = normalErr.back();
    c.medianNormalErrorDeg = normalErr[normalErr.size() / 2];
  }
  return c;
}

inline tensor::GlyphSet glyphsOf(const io::TensorField& f) { return tensor::buildGlyphs(f.positions, f.tensors, f.ids); }

inline render::Camera cameraFor(const tensor::GlyphSet& s, double scale, render::CameraDesc d, int w, int h) {
  const double pad = scale * s.maxAbsEigenvalue;
  return render::makeCamera(d, w, h, s.boundsMinWC - pad, s.boundsMaxWC + pad);
}

inline render::CameraDesc oblique(const tensor::GlyphSet& s, double dist, render::Projection p) {
  render::CameraDesc d;
  d.lookAtWC = 0.5 * (s.boundsMinWC + s.boundsMaxWC);
  d.eyeWC = d.lookAtWC + dist * glm::normalize(glm::dvec3(0.7, -1.1, 0.9));
  d.upWC = {0, 0, 1};
  d.projection = p;
  d.orthoHeight = 0.9 * dist;
  return d;
}

class GlFixture : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ctx_ = gl::createOSMesaContext();
    lib_ = std::make_unique<gl::ShaderLibrary>();
  }
  static void TearDownTestSuite() {
    lib_.reset();
    ctx_.reset();
  }
  render::FrameImage draw(const tensor::GlyphSet& set, const render::Camera& cam, const render::FrameParams& p) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    r.render(cam, p, target);
    return r.readback(cam, target);
  }
  static inline std::unique_ptr<gl::Context> ctx_;
  static inline std::unique_ptr<gl::ShaderLibrary> lib_;
};

}  // namespace tg::test
