// Tier 1: Blinn's blobs as the cpu path casts them (render::castBlobs, over
// shaders/lib/blob.glsl compiled as C++) against the double-precision,
// untruncated reference (ref::renderBlobs), and the properties that make a
// blob a blob: a lone bump is its glyph, neighbours merge as the
// blobbiness nears 0 and part as it grows, the threshold grows or shrinks
// the surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "cpu_frame.h"
#include "ref/blob_ref.h"
#include "ref/ellipsoid_ref.h"
#include "ref/image_diff.h"
#include "ref/superquadric_ref.h"
#include "render/cpu_blobs.h"

using namespace tg;

namespace {

// Symmetric tensor R diag(l) R^T as xx xy xz yy yz zz.
void addTensor(std::vector<float>& ten, const glm::dvec3& l, double a, double b) {
  const glm::dmat3 r = glm::dmat3(glm::rotate(glm::dmat4(1.0), a, glm::dvec3(0, 0, 1)) *
                                  glm::rotate(glm::dmat4(1.0), b, glm::dvec3(0, 1, 0)));
  const glm::dmat3 d = r * glm::dmat3(l.x, 0, 0, 0, l.y, 0, 0, 0, l.z) * glm::transpose(r);
  ten.insert(ten.end(), {float(d[0][0]), float(d[1][0]), float(d[2][0]), float(d[1][1]), float(d[2][1]), float(d[2][2])});
}

// A chain of prolate glyphs along x, `gap` apart between their tips at
// scale 1 (semi-axes 0.6, 0.25, 0.25); and a 3x3x3 block of tilted ones.
tensor::GlyphSet chain(int n, double gap) {
  std::vector<float> pos, ten;
  for (int k = 0; k < n; ++k) {
    pos.insert(pos.end(), {float(k * (1.2 + gap)), 0.0f, 0.0f});
    addTensor(ten, {0.6, 0.25, 0.25}, 0.0, 0.0);
  }
  return tensor::buildGlyphs(pos, ten, {});
}

tensor::GlyphSet block() {
  std::vector<float> pos, ten;
  for (int k = 0; k < 27; ++k) {
    pos.insert(pos.end(), {float(k % 3), float(k / 3 % 3), float(k / 9)});
    addTensor(ten, {0.45, 0.3 - 0.005 * k, 0.2}, 0.7 * k, 1.3 * k);
  }
  return tensor::buildGlyphs(pos, ten, {});
}

render::Camera blobCamera(const tensor::GlyphSet& s, render::Projection proj, int w, int h) {
  render::CameraDesc d;
  d.lookAtWC = 0.5 * (s.boundsMinWC + s.boundsMaxWC);
  const double size = glm::length(s.boundsMaxWC - s.boundsMinWC) + 2.0;
  d.eyeWC = d.lookAtWC + 2.0 * size * glm::normalize(glm::dvec3(0.3, -1.1, 0.6));
  d.upWC = {0, 0, 1};
  d.projection = proj;
  d.orthoHeight = 0.8 * size;
  d.fovYDeg = 30.0;
  // The bumps reach about 2.4 glyph radii at the defaults.
  return render::makeCamera(d, w, h, s.boundsMinWC - 3.0, s.boundsMaxWC + 3.0);
}

ref::RefParams refParams(const render::FrameParams& p) {
  ref::RefParams r{p.scale, p.faMin, p.sizing};
  r.blobThreshold = p.blob.threshold;
  r.blobBlobbiness = p.blob.blobbiness;
  return r;
}

render::FrameParams blobParams() {
  render::FrameParams p;
  p.glyph = render::GlyphKind::Blob;
  p.gamma = 0.0;
  return p;
}

struct Cast {
  render::CpuCasts casts;
  std::vector<render::BlobCandidate> bumps;
  std::uint64_t drawn = 0;
};

Cast cast(const tensor::GlyphSet& set, const render::Camera& cam, const render::FrameParams& p, int threads = 2) {
  Cast c;
  c.drawn = render::castBlobs(set.glyphs, cam, p, false, threads, c.casts, c.bumps);
  return c;
}

std::size_t covered(const render::CpuCasts& c) {
  std::size_t n = 0;
  for (const std::uint32_t r : c.record) n += r != 0;
  return n;
}

}  // namespace

// At threshold 1 a lone bump's surface is g = 1: its glyph, the exact
// ellipsoid (gamma 0) or the superquadric (gamma 3), to the reference's
// tolerances for the shared casts (test_cpu_casts.cpp) but for depth, which
// here comes from regula falsi on the sum in float (relative 1e-6).
TEST(Blob, ALoneBumpIsItsGlyph) {
  std::vector<float> pos = {0, 0, 0}, ten;
  addTensor(ten, {0.9, 0.5, 0.3}, 0.4, 0.9);
  const tensor::GlyphSet set = tensor::buildGlyphs(pos, ten, {});
  for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic})
    for (const double gamma : {0.0, 3.0}) {
      SCOPED_TRACE("gamma " + std::to_string(gamma));
      render::FrameParams p = blobParams();
      p.gamma = gamma;
      const render::Camera cam = blobCamera(set, proj, 120, 100);
      const Cast c = cast(set, cam, p);
      const ref::RefImage glyph = gamma == 0.0 ? ref::renderEllipsoids(cam, set.glyphs, {1.0, 0.0})
                                               : ref::renderSuperquadrics(cam, set.glyphs, {1.0, 0.0}, gamma);
      const ref::ImageDiff d = ref::diffImages(test::asFrame(c.casts, set, cam), glyph, cam);
      EXPECT_GT(d.refCovered, 1000u);
      EXPECT_EQ(d.interiorMismatch, 0u);
      EXPECT_LE(double(d.coverageMismatch), 0.01 * double(d.refCovered));
      EXPECT_EQ(d.idMismatch, 0u);
      EXPECT_LT(d.depth.max, 1e-5);
      EXPECT_LT(d.normalDeg.median, 0.05);
      EXPECT_LT(d.normalDeg.max, 1.0);
    }
}

// The truncated, sampled cast against the untruncated double-precision
// reference at the defaults (cutoff 1e-3, 4 steps): coverage within the
// issue's 0.1% (counted against the reference's pixels), none of it off the
// silhouettes; depth and normals off the silhouettes and the seams where
// the dominant bump changes, within the truncation's effect (K t T / (1 -
// t) on the sum, at most a few 1e-4 of the surface's distance).
TEST(Blob, CastMatchesTheDoublePrecisionReference) {
  const tensor::GlyphSet sets[2] = {chain(5, 0.1), block()};
  for (const tensor::GlyphSet& set : sets)
    for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic})
      for (const double gamma : {0.0, 3.0}) {
        SCOPED_TRACE(std::string(&set == &sets[0] ? "chain" : "block") + ", gamma " + std::to_string(gamma));
        render::FrameParams p = blobParams();
        p.gamma = gamma;
        const render::Camera cam = blobCamera(set, proj, 128, 96);
        const Cast c = cast(set, cam, p);
        EXPECT_EQ(c.drawn, set.glyphs.size());
        const ref::ImageDiff d = ref::diffImages(test::asFrame(c.casts, set, cam),
                                                 ref::renderBlobs(cam, set.glyphs, refParams(p), gamma), cam);
        EXPECT_GT(d.refCovered, &set == &sets[0] ? 300u : 1500u);
        EXPECT_EQ(d.interiorMismatch, 0u);
        EXPECT_LE(double(d.coverageMismatch), 0.001 * double(d.refCovered));
        std::printf("[ blob ] %s, gamma %g, %s: %zu pixels, %zu coverage mismatches, depth p99 %.2g, normal median %.3g p99 %.3g deg\n",
                    &set == &sets[0] ? "chain" : "block", gamma, proj == render::Projection::Perspective ? "persp" : "ortho",
                    d.refCovered, d.coverageMismatch, d.depth.p99, d.normalDeg.median, d.normalDeg.p99);
        EXPECT_LT(d.depth.p99, 1e-4);
        EXPECT_LT(d.normalDeg.median, 0.1);
        EXPECT_LT(d.normalDeg.p99, 2.0);
      }
}

// Blinn's blobbiness: glyphs 0.3 apart tip to tip join at B = -1 (each bump
// gives 0.70 at the midpoint, together 1.4 > T) and stay apart at B = -8,
// where each glyph's blob is nearly the glyph; the gap's middle pixel shows
// it. The threshold grows (T < 1) and shrinks (T > 1) the surface.
TEST(Blob, BlobbinessJoinsNeighboursAndTheThresholdSizesThem) {
  const tensor::GlyphSet set = chain(2, 0.3);
  render::CameraDesc d;
  d.lookAtWC = {0.75, 0, 0};
  d.eyeWC = {0.75, -10, 0};
  d.upWC = {0, 0, 1};
  d.projection = render::Projection::Orthographic;
  d.orthoHeight = 2.0;
  const render::Camera cam = render::makeCamera(d, 200, 100, glm::dvec3(-4), glm::dvec3(5));
  // The gap's middle, x = 0.75 WC: the centre column of the image, middle row.
  const std::size_t middle = std::size_t(50) * 200 + 100;
  render::FrameParams p = blobParams();
  const ref::RefImage glyphs = ref::renderEllipsoids(cam, set.glyphs, {1.0, 0.0});
  ASSERT_EQ(glyphs.id[std::size_t(49) * 200 + 100], ref::kNoGlyph) << "the glyphs themselves leave a gap";
  p.blob.blobbiness = -1.0;
  const Cast joined = cast(set, cam, p);
  EXPECT_NE(joined.casts.record[middle], 0u);
  p.blob.blobbiness = -8.0;
  const Cast apart = cast(set, cam, p);
  EXPECT_EQ(apart.casts.record[middle], 0u);
  p.blob.blobbiness = -2.0;
  const std::size_t at1 = covered(cast(set, cam, p).casts);
  p.blob.threshold = 0.5;
  const std::size_t at05 = covered(cast(set, cam, p).casts);
  p.blob.threshold = 2.0;
  const std::size_t at2 = covered(cast(set, cam, p).casts);
  EXPECT_GT(at05, at1 + 500);
  EXPECT_LT(at2 + 500, at1);
  EXPECT_GT(at2, 0u);
}

// The reference's own sum: 1 on a lone glyph's surface, whatever the
// blobbiness, and exp(-B) at its centre.
TEST(Blob, TheSumIsOneOnALoneGlyphsSurface) {
  std::vector<float> pos = {1, 2, 3}, ten;
  addTensor(ten, {0.9, 0.5, 0.3}, 0.4, 0.9);
  const tensor::GlyphSet set = tensor::buildGlyphs(pos, ten, {});
  glm::dvec3 frame[3];
  tensor::frameAxes(set.glyphs[0], frame);
  for (const double b : {-0.5, -2.0, -6.0}) {
    ref::RefParams r;
    r.blobBlobbiness = b;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 onSurface = glm::dvec3(1, 2, 3) + std::abs(double(set.glyphs[0].eigenvalues[k])) * frame[k];
      EXPECT_NEAR(ref::blobSum(set.glyphs, r, 0.0, onSurface), 1.0, 1e-6) << "axis " << k << ", B " << b;
    }
    EXPECT_NEAR(ref::blobSum(set.glyphs, r, 0.0, glm::dvec3(1, 2, 3)), std::exp(-b), 1e-9 * std::exp(-b));
  }
}

// A flat tensor's bump (an eigenvalue 0) keeps a thickness a float ray
// samples (tensor::kBlobMinAxisRatio): seen face-on and edge-on, it covers
// what its glyph's disc does, and not nothing.
TEST(Blob, AFlatTensorsBumpIsDrawn) {
  std::vector<float> pos = {0, 0, 0}, ten = {2, 0, 0, 1, 0, 0};
  const tensor::GlyphSet set = tensor::buildGlyphs(pos, ten, {});
  for (const glm::dvec3 eye : {glm::dvec3(0.1, 0.2, 10), glm::dvec3(3, 2, 8)}) {
    render::CameraDesc d;
    d.eyeWC = eye;
    d.projection = render::Projection::Orthographic;
    d.orthoHeight = 5.0;
    const render::Camera cam = render::makeCamera(d, 100, 80, glm::dvec3(-6), glm::dvec3(6));
    const ref::RefImage glyph = ref::renderEllipsoids(cam, set.glyphs, {1.0, 0.0});
    const auto disc = std::size_t(
        std::count_if(glyph.id.begin(), glyph.id.end(), [](std::uint32_t id) { return id != ref::kNoGlyph; }));
    ASSERT_GT(disc, 500u);
    const std::size_t blob = covered(cast(set, cam, blobParams()).casts);
    EXPECT_GT(double(blob), 0.95 * double(disc));
    EXPECT_LT(double(blob), 1.05 * double(disc));
  }
}

// The set-up runs on any number of threads to the same casts.
TEST(Blob, ThreadsCastTheSamePixels) {
  const tensor::GlyphSet set = block();
  const render::Camera cam = blobCamera(set, render::Projection::Perspective, 96, 80);
  const render::FrameParams p = blobParams();
  const Cast one = cast(set, cam, p, 1), three = cast(set, cam, p, 3);
  EXPECT_EQ(one.casts.ownRecord, three.casts.ownRecord);
  EXPECT_EQ(one.casts.ownDepth, three.casts.ownDepth);
}
