// Tier 3: the superquadric pass's occlusion pre-pass (GlyphRenderer::render,
// shaders/lib/occlusion.glsl) changes what a frame costs, never what it shows.
// Exact equality is the bound: a skipped fragment is one that would have lost
// the depth test.
#include "frame_compare.h"
#include "render/raster_glyphs.h"
#include "render_fixture.h"

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

using namespace tg;
using test::GlFixture;

namespace {

// A dense block of glyphs seen from close by, so that most lie behind others.
io::TensorField denseBlock(int n, bool mixedSigns) {
  io::TensorField f;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uint32_t id = 0;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x, ++id) {
        const double shift = mixedSigns && id % 2 == 0 ? 0.0 : 2.2;
        double t[9] = {shift + u(rng), 0.6 * u(rng), 0.6 * u(rng), 0, shift + u(rng), 0.6 * u(rng), 0, 0, shift + u(rng)};
        t[3] = t[1], t[6] = t[2], t[7] = t[5];
        const double p[3] = {double(x), double(y), double(z)};
        f.addFull(id, p, t);
      }
  return f;
}

render::Camera closeCamera(const tensor::GlyphSet& set, double scale, int w, int h) {
  render::CameraDesc d;
  d.lookAtWC = 0.5 * (set.boundsMinWC + set.boundsMaxWC);
  d.eyeWC = d.lookAtWC + glm::dvec3(0.3, -0.5, 1.0) * (0.9 * (set.boundsMaxWC.z - set.boundsMinWC.z));
  d.upWC = {0, 1, 0};
  d.fovYDeg = 50;
  return test::cameraFor(set, scale, d, w, h);
}

class Occlusion : public GlFixture {
 protected:
  struct Frame {
    render::FrameImage img;
    render::IterationStats stats;
    std::uint64_t prepasses;
  };
  Frame frame(const tensor::GlyphSet& set, const render::Camera& cam, render::FrameParams p) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    p.iterationStats = true;
    r.render(cam, p, target);
    return {r.readback(cam, target), r.iterationStats(), render::asRaster(r.glyphPath()).occlusionPrepasses()};
  }
  // A superquadric frame (gamma 3 unless given) whose pre-pass's occluder
  // depth is read back, rows bottom-up as GL's, with the image and the
  // pre-passes run.
  struct OccluderFrame {
    render::FrameImage img;
    std::vector<float> occluderDepth;
    std::uint64_t prepasses;
  };
  OccluderFrame occluderFrame(const tensor::GlyphSet& set, const render::Camera& cam, double scale,
                              render::GBuffer& target, double gamma = 3.0) {
    ctx_->makeCurrent();
    const gl::Api& gl = ctx_->api();
    render::GlyphRenderer r(gl, *lib_);
    r.upload(set);
    r.render(cam, test::superquadricParams(scale, gamma), target);
    std::vector<float> depth(std::size_t(cam.width) * cam.height);
    gl.GetTextureImage(target.occluderDepth(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * 4), depth.data());
    return {r.readback(cam, target), std::move(depth), render::asRaster(r.glyphPath()).occlusionPrepasses()};
  }
};

std::size_t differing(const render::FrameImage& a, const render::FrameImage& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.id.size(); ++i)
    n += a.id[i] != b.id[i] || a.rgba[4 * i] != b.rgba[4 * i] || a.depth[i] != b.depth[i];
  return n;
}

}  // namespace

// Every pyramid texel is the farthest (smallest reversed window depth)
// occluder depth over exactly the pixels under it, odd sizes included.
TEST_F(Occlusion, PyramidTexelsHoldTheFarthestDepthUnderThem) {
  const auto set = test::glyphsOf(denseBlock(7, false));
  const double scale = 0.5 / set.maxAbsEigenvalue;
  for (const auto& [w, h] : {std::pair{97, 61}, std::pair{128, 64}}) {
    SCOPED_TRACE(w);
    const auto cam = closeCamera(set, scale, w, h);
    const gl::Api& gl = ctx_->api();
    render::GBuffer target(gl, w, h);
    const std::vector<float> depth = occluderFrame(set, cam, scale, target).occluderDepth;
    std::size_t covered = 0;
    for (float z : depth) covered += z > 0.0f;
    ASSERT_GT(covered, depth.size() / 2);
    ASSERT_LT(covered, depth.size());
    for (int m = 0; m < target.pyramidLevels(); ++m) {
      const int mw = std::max(1, target.pyramidWidth() >> m), mh = std::max(1, target.pyramidHeight() >> m);
      std::vector<float> level(std::size_t(mw) * mh);
      gl.GetTextureImage(target.occluderPyramid(), m, GL_RED, GL_FLOAT, GLsizei(level.size() * 4), level.data());
      const int k = m + 1;  // texel i of mip m covers pixels [i 2^k, (i + 1) 2^k), the last one to the edge
      for (int j = 0; j < mh; ++j)
        for (int i = 0; i < mw; ++i) {
          float farthest = 1.0f;
          const int x1 = i == mw - 1 ? w : std::min(w, (i + 1) << k), y1 = j == mh - 1 ? h : std::min(h, (j + 1) << k);
          for (int y = j << k; y < y1; ++y)
            for (int x = i << k; x < x1; ++x) farthest = std::min(farthest, depth[std::size_t(y) * w + x]);
          ASSERT_EQ(level[std::size_t(j) * mw + i], farthest) << "mip " << m << " texel " << i << "," << j;
        }
    }
    gl::checkError(gl, "PyramidTexelsHoldTheFarthestDepthUnderThem");
  }
}

// The pre-pass's occluders are discs at the farthest depth of each
// ellipsoid's silhouette contour (ellipsoid.vert TG_OCCLUDER_DISC): wherever
// one was drawn, the frame shows a surface, and none behind it (beyond the
// march's tolerance). Perspective and orthographic, from outside the block
// and from among the glyphs, where the near plane cuts some of them.
TEST_F(Occlusion, OccludersNeverLieInFrontOfTheVisibleSurface) {
  const auto set = test::glyphsOf(denseBlock(7, false));
  const double scale = 0.5 / set.maxAbsEigenvalue;
  const double toleranceWC = 4.0 * render::MarchParams{}.epsilon * scale * set.maxAbsEigenvalue;
  const glm::dvec3 mid = 0.5 * (set.boundsMinWC + set.boundsMaxWC);
  for (const bool inside : {false, true})
    for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
      SCOPED_TRACE(::testing::Message() << "inside " << inside << " ortho " << (proj == render::Projection::Orthographic));
      render::CameraDesc d = test::oblique(set, inside ? 0.4 : 9.0, proj);
      d.lookAtWC = inside ? mid + glm::dvec3(3.0, 3.0, -3.0) : mid;
      if (inside) d.eyeWC = mid + glm::dvec3(0.05, -0.1, 0.02);
      const int w = 150, h = 110;
      const auto cam = test::cameraFor(set, scale, d, w, h);
      const gl::Api& gl = ctx_->api();
      render::GBuffer target(gl, w, h);
      const OccluderFrame f = occluderFrame(set, cam, scale, target);
      ASSERT_EQ(f.prepasses, 1u);
      const render::FrameImage& img = f.img;
      const std::vector<float>& occluder = f.occluderDepth;
      std::size_t occluded = 0, covered = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const std::size_t i = std::size_t(h - 1 - y) * w + x;  // the image's rows run top-down
          covered += img.id[i] != ref::kNoGlyph;
          const float z = occluder[std::size_t(y) * w + x];
          if (!(z > 0.0f)) continue;
          ++occluded;
          ASSERT_NE(img.id[i], ref::kNoGlyph) << x << "," << y;
          const double occluderVC = cam.viewDepthFromWindowDepth(z);
          ASSERT_LE(img.depth[i], occluderVC * (1.0 + 1e-5) + toleranceWC) << x << "," << y;
        }
      EXPECT_GT(occluded, covered / 2);
      gl::checkError(gl, "OccludersNeverLieInFrontOfTheVisibleSurface");
    }
}

// The frame is the same with and without the pre-pass, for definite glyphs
// (which occlude) and mixed signs (which are only occluded), at several gammas,
// and the march runs on far fewer pixels with it.
TEST_F(Occlusion, PrepassChangesTheWorkNotTheImage) {
  for (const bool mixed : {false, true}) {
    const auto set = test::glyphsOf(denseBlock(9, mixed));
    const double scale = 0.5 / set.maxAbsEigenvalue;
    const auto cam = closeCamera(set, scale, 200, 150);
    for (const double gamma : {0.0, 1.0, 3.0, 8.0}) {
      SCOPED_TRACE(::testing::Message() << "mixed " << mixed << " gamma " << gamma);
      render::FrameParams p = test::superquadricParams(scale, gamma);
      p.occlusionPrepass = false;
      const Frame plain = frame(set, cam, p);
      p.occlusionPrepass = true;
      const Frame occluded = frame(set, cam, p);
      EXPECT_EQ(differing(plain.img, occluded.img), 0u);
      EXPECT_EQ(plain.prepasses, 0u);
      EXPECT_EQ(occluded.prepasses, 1u);
      std::size_t covered = 0;
      for (auto id : plain.img.id) covered += id != ref::kNoGlyph;
      EXPECT_GT(covered, plain.img.id.size() / 2);
      // Definite glyphs all occlude: most marches go. With mixed signs only
      // half the glyphs occlude (and at gamma 0 only the mixed ones march).
      if (!mixed && gamma > 0.0) {
        EXPECT_LT(2 * occluded.stats.pixels, plain.stats.pixels);
      }
      if (mixed) {
        EXPECT_LT(double(occluded.stats.pixels), 0.9 * double(plain.stats.pixels));
      }
    }
  }
}

// Mixed-sign glyphs alone (a stress field) hold no ellipsoid, so nothing can
// occlude: the pre-pass does not run, and the frame is unchanged.
TEST_F(Occlusion, NoPrepassWithoutOccluders) {
  io::TensorField f;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.3, 1.0);
  for (std::uint32_t i = 0; i < 6 * 6 * 6; ++i) {
    const double t[9] = {u(rng), 0, 0, 0, -u(rng), 0, 0, 0, 0.5 * u(rng)};
    const double p[3] = {double(i % 6), double(i / 6 % 6), double(i / 36)};
    f.addFull(i, p, t);
  }
  const auto set = test::glyphsOf(f);
  ASSERT_EQ(set.sphereCount + set.definiteCount, 0u);
  const double scale = 0.5 / set.maxAbsEigenvalue;
  const auto cam = closeCamera(set, scale, 160, 120);
  render::FrameParams p = test::superquadricParams(scale);
  const Frame on = frame(set, cam, p);
  p.occlusionPrepass = false;
  const Frame off = frame(set, cam, p);
  EXPECT_EQ(on.prepasses, 0u);
  EXPECT_EQ(differing(on.img, off.img), 0u);
  EXPECT_GT(on.stats.pixels, 1000u);
}

// Spheres (and, at gamma 0, definite glyphs) are occluder discs in the
// pre-pass and exact ellipsoids in the G-buffer, where those wholly behind
// the pyramid stop in the vertex stage (ellipsoid.vert). A dense block of
// spheres with one mixed-sign glyph (so that the march and its pre-pass
// run): the frame is unchanged, and the spheres are not shaded twice over.
TEST_F(Occlusion, HiddenSpheresSkipTheGeometryPass) {
  io::TensorField f;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.6, 1.0);
  const int n = 12;
  for (std::uint32_t i = 0; i < std::uint32_t(n * n * n); ++i) {
    const double s = u(rng);
    double t[9] = {s, 0, 0, 0, s, 0, 0, 0, s};
    if (i == 0) t[4] = -0.5 * s;  // the one mixed-sign glyph
    const double p[3] = {double(i % n), double(i / n % n), double(i / (n * n))};
    f.addFull(i, p, t);
  }
  const auto set = test::glyphsOf(f);
  ASSERT_GT(set.sphereCount, std::size_t(n * n * n) - 2);
  const double scale = 0.55 / set.maxAbsEigenvalue;
  const auto cam = closeCamera(set, scale, 160, 120);
  const gl::Api& gl = ctx_->api();
  auto shaded = [&](bool prepass, render::FrameImage& img) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(gl, *lib_);
    render::GBuffer target(gl, cam.width, cam.height);
    r.upload(set);
    render::FrameParams p = test::superquadricParams(scale, 3.0);
    p.occlusionPrepass = prepass;
    const GLuint64 fragments = test::countedBy(gl, GL_FRAGMENT_SHADER_INVOCATIONS, [&] { r.render(cam, p, target); });
    EXPECT_EQ(render::asRaster(r.glyphPath()).occlusionPrepasses(), prepass ? 1u : 0u);
    img = r.readback(cam, target);
    return double(fragments);
  };
  render::FrameImage plain, culled;
  const double without = shaded(false, plain), with = shaded(true, culled);
  EXPECT_EQ(test::differingPixels(plain, culled), 0u);
  EXPECT_GT(test::coveredPixels(plain), plain.id.size() / 2);
  // The pre-pass's discs shade at most every sphere's outline once; were the
  // hidden ones shaded again in the G-buffer, the frame would shade about
  // twice as many fragments.
  EXPECT_LT(with, 1.5 * without);
}

// Thin definite glyphs (discs and needles, down to kMinAxisRatio) in random
// orientations before a wide mixed-sign glyph: an occluder claims no pixel
// where the frame drawn without the pre-pass shows nothing in front of its
// depth, so the frame is the same with it. A 1e-7 disc's own ray cast
// misses some pixels inside its outline, and a needle's outline conic rounds
// wider than the needle: such glyphs must occlude nothing.
TEST_F(Occlusion, ThinOccludersClaimNoPixelTheirGlyphMisses) {
  for (const double thin : {1e-7, 1e-5, 1e-3}) {
    io::TensorField f;
    std::mt19937_64 rng(7);
    std::normal_distribution<double> nd(0.0, 1.0);
    std::uint32_t id = 0;
    for (; id < 48; ++id) {
      const glm::dvec3 n = glm::normalize(glm::dvec3(nd(rng), nd(rng), nd(rng)));
      const bool needle = id % 2 == 1;
      // Disc: I - (1 - thin) n n^T; needle: thin I + (1 - thin) n n^T.
      double t[9];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double nn = (1.0 - thin) * n[i] * n[j], unit = i == j ? 1.0 : 0.0;
          t[3 * i + j] = needle ? thin * unit + nn : unit - nn;
        }
      const double p[3] = {0.6 * (id % 8) - 2.1, 0.6 * (id / 8) - 1.5, 0.0};
      f.addFull(id, p, t);
    }
    const double back[9] = {9, 0, 0, 0, 7, 0, 0, 0, -0.5}, behind[3] = {0, 0, -3};
    f.addFull(id, behind, back);
    const auto set = test::glyphsOf(f);
    ASSERT_EQ(set.definiteCount, 48u);
    const double scale = 0.3;
    render::CameraDesc d;
    d.eyeWC = {0.2, -0.3, 4.0};
    d.fovYDeg = 40;
    const auto cam = test::cameraFor(set, scale, d, 200, 150);
    for (const double gamma : {0.0, 3.0}) {
      SCOPED_TRACE(::testing::Message() << "thin " << thin << " gamma " << gamma);
      render::GBuffer target(ctx_->api(), cam.width, cam.height);
      const OccluderFrame with = occluderFrame(set, cam, scale, target, gamma);
      ASSERT_EQ(with.prepasses, 1u);
      render::FrameParams p = test::superquadricParams(scale, gamma);
      p.occlusionPrepass = false;
      const render::FrameImage without = draw(set, cam, p);
      std::size_t claimed = 0, nothingInFront = 0;
      for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
          const float z = with.occluderDepth[std::size_t(y) * cam.width + x];
          if (!(z > 0.0f)) continue;
          ++claimed;
          const double occluderVC = cam.viewDepthFromWindowDepth(z);
          nothingInFront += !(without.depth[std::size_t(cam.height - 1 - y) * cam.width + x] <=
                              occluderVC * (1.0 + 1e-5) + 4.0 * render::MarchParams{}.epsilon * scale);
        }
      if (thin >= 1e-3) {
        EXPECT_GT(claimed, 1000u);
      }
      EXPECT_EQ(nothingInFront, 0u);
      EXPECT_EQ(differing(with.img, without), 0u);
    }
  }
}

// Orthographic rays see glyphs behind the eye's plane too (negative view
// depth, down to the near plane below the scene). A mixed-sign glyph just in
// front of a unit sphere (1.3 before its centre, where the sphere's occluder
// disc lies), the scene 1e4 and 1e6 behind the eye: the depth margin must
// not turn into a cut as the depth turns negative.
TEST_F(Occlusion, OrthographicScenesBehindTheEyeKeepTheirGlyphs) {
  io::TensorField f;
  const double sphere[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, atSphere[3] = {0, 0, 0};
  const double mixed[9] = {0.3, 0, 0, 0, -0.25, 0, 0, 0, 0.05}, inFront[3] = {0, 0, 1.3};
  f.addFull(0, atSphere, sphere);
  f.addFull(1, inFront, mixed);
  const auto set = test::glyphsOf(f);
  for (const double behind : {1e4, 1e6}) {
    render::CameraDesc d;
    d.projection = render::Projection::Orthographic;
    d.eyeWC = {0.01, 0.02, -behind};
    d.lookAtWC = d.eyeWC - glm::dvec3(0, 0, 1);
    d.orthoHeight = 3.0;
    const auto cam = test::cameraFor(set, 1.0, d, 200, 200);
    SCOPED_TRACE(::testing::Message() << "behind " << behind << " near " << cam.nearVC);
    ASSERT_LT(cam.nearVC, -behind);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    const OccluderFrame with = occluderFrame(set, cam, 1.0, target);
    EXPECT_EQ(with.prepasses, 1u);
    render::FrameParams p = test::superquadricParams(1.0);
    p.occlusionPrepass = false;
    const render::FrameImage without = draw(set, cam, p);
    std::size_t mixedPixels = 0;
    for (auto id : without.id) mixedPixels += id == 1;
    EXPECT_GT(mixedPixels, 200u);
    EXPECT_EQ(differing(with.img, without), 0u);
  }
}
