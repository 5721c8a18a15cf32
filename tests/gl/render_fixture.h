#pragma once
// Tier 3 helpers: render on a real GL context and compare with the CPU reference.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

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
        // Two glyphs whose surfaces meet at the same depth (same-shaped cones
        // on one axis do) may win either way; that is a tie, not an error.
        const bool tie = std::abs(g.depth[p] - r.depth[p]) <= 1e-6 * r.depth[p];
        if (!onEdge(i, j) && !tie) ++c.idMismatch;
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

// What a GPU render may differ from the reference by; each test file states
// why its values are what they are.
struct Tolerance {
  double interiorMismatch, coverageMismatch, idMismatch;  // fractions of the reference's covered pixels
  double relDepth, medianNormalDeg, maxNormalDeg;
};

inline void expectWithin(const Comparison& c, const Tolerance& t, const std::string& what) {
  SCOPED_TRACE(what);
  const double covered = double(c.refCovered);
  EXPECT_GT(c.refCovered, 0u);
  EXPECT_EQ(c.nonFinite, 0u);
  EXPECT_LE(double(c.interiorMismatch), t.interiorMismatch * covered);
  EXPECT_LE(double(c.coverageMismatch), t.coverageMismatch * covered);
  EXPECT_LE(double(c.idMismatch), t.idMismatch * covered);
  EXPECT_LT(c.maxRelDepthError, t.relDepth);
  EXPECT_LT(c.medianNormalErrorDeg, t.medianNormalDeg);
  EXPECT_LT(c.maxNormalErrorDeg, t.maxNormalDeg);
}

// Three glyphs around and beside the eye of insideCamera(): the eye plane cuts
// them, so no finite rectangle exists and some rays start inside glyph 0.
inline tensor::GlyphSet glyphsAroundTheEye() {
  const float pos[9] = {0, 0, 0, 1.5f, 0.3f, -0.2f, -0.4f, 2.0f, 0.1f};
  const float ten[18] = {2, 0, 0, 1, 0, 0.8f, 1, 0.2f, 0, 0.5f, 0, 0.5f, 0.7f, 0, 0.1f, 0.7f, 0, 0.3f};
  return tensor::buildGlyphs(std::span(pos, 9), std::span(ten, 18), {});
}

inline render::Camera insideCamera(render::Projection proj) {
  render::CameraDesc d;
  d.eyeWC = {0.3, -0.2, 0.1};  // inside glyph 0
  d.lookAtWC = {1, 1, 0};
  d.upWC = {0, 0, 1};
  d.projection = proj;
  d.fovYDeg = 70;
  d.orthoHeight = 3;
  return render::makeCamera(d, 160, 120, glm::dvec3(-3), glm::dvec3(3));
}

// The extremes gallery at eigenvalue scale 1e20 and positions 1e6 (k = 1e6),
// or 1e-20 and 1e-6: the base scene's picture, k times larger or smaller.
struct ScaledWorld {
  tensor::GlyphSet set;
  double scale;
  render::Camera cam;
};
inline ScaledWorld scaledExtremes(double k) {
  const double eigenScale = k > 1 ? 1e20 : 1e-20;
  auto set = glyphsOf(synth::extremesGallery(eigenScale, k));
  const double scale = k / eigenScale;
  const auto cam = cameraFor(set, scale, oblique(set, 40.0 * k, render::Projection::Perspective), 160, 80);
  return {std::move(set), scale, cam};
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
