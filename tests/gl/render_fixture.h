#pragma once
// Tier 3 helpers: render on a real GL context and compare with the CPU reference.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "gl/backends.h"
#include "gl/shader_library.h"
#include "ref/ellipsoid_ref.h"
#include "ref/image_diff.h"
#include "ref/superquadric_ref.h"
#include "data-synthetic/generators.h"
#include "render/renderer.h"

namespace tg::test {

using Comparison = ref::ImageDiff;

// The draw must read back every channel (the fixture's draw() does).
inline Comparison compare(const render::FrameImage& g, const ref::RefImage& r, const render::Camera& cam) {
  return ref::diffImages(g, r, cam);
}

inline tensor::GlyphSet glyphsOf(const io::TensorField& f) { return tensor::buildGlyphs(f.positions, f.tensors, f.ids); }

// An n^3 grid of every dispatch group: each 5th tensor a sphere, each 3rd
// definite, the rest with mixed signs. With minSize < 1 each tensor is also
// scaled by a factor from [minSize, 1], so that at a pixel's scale some
// glyphs are seen and most are not.
inline io::TensorField mixedGrid(std::uint32_t n, std::uint64_t seed, double minSize = 1.0) {
  io::TensorField f;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::uint32_t i = 0; i < n * n * n; ++i) {
    const double shift = i % 3 == 0 ? 2.5 : 0.0, iso = u(rng);
    double t[9] = {shift + u(rng), u(rng), u(rng), 0, shift + u(rng), u(rng), 0, 0, shift + u(rng)};
    if (i % 5 == 0) t[0] = t[4] = t[8] = iso, t[1] = t[2] = t[5] = 0;
    t[3] = t[1], t[6] = t[2], t[7] = t[5];
    if (minSize < 1.0) {
      const double k = std::uniform_real_distribution<double>(minSize, 1.0)(rng);
      for (double& v : t) v *= k;
    }
    const double p[3] = {double(i % n), double(i / n % n), double(i / (n * n))};
    f.addFull(i, p, t);
  }
  return f;
}

// Frame parameters that draw every glyph as a superquadric, at `scale`
// world units per eigenvalue unit and sharpness `gamma`.
inline render::FrameParams superquadricParams(double scale, double gamma = render::FrameParams{}.gamma) {
  render::FrameParams p;
  p.scale = scale;
  p.glyph = render::GlyphKind::Superquadric;
  p.gamma = gamma;
  return p;
}

inline render::Camera cameraFor(const tensor::GlyphSet& s, double scale, render::CameraDesc d, int w, int h) {
  const auto [lo, hi] = tensor::glyphBoxWC(s, scale);
  return render::makeCamera(d, w, h, lo, hi);
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
  EXPECT_LT(c.depth.max, t.relDepth);
  EXPECT_LT(c.normalDeg.median, t.medianNormalDeg);
  EXPECT_LT(c.normalDeg.max, t.maxNormalDeg);
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
  // On the first glyph path that draws p's kind (the raster path but for blobs).
  render::FrameImage draw(const tensor::GlyphSet& set, const render::Camera& cam, const render::FrameParams& p) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_, nullptr, render::pathDraws("raster", p.glyph) ? "raster" : "cpu");
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    r.render(cam, p, target);
    return r.readback(cam, target);
  }
  static inline std::unique_ptr<gl::Context> ctx_;
  static inline std::unique_ptr<gl::ShaderLibrary> lib_;
};

}  // namespace tg::test
