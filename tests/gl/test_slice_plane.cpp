// Slice planes (render/slice_plane.h) against the CPU reference and their
// contracts: world placement through the underlay's own grid, the depth
// offset that keeps glyphs on the plane whole, and a golden image.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/render_fixture.h"
#include "io/core/image_writer.h"
#include "ref/plane_ref.h"
#include "render/slice_plane.h"
#include "gl/golden.h"

namespace tg::test {
namespace {

// A volume of f(p) = 0.5 + 0.1 p.x - 0.07 p.y + 0.03 p.z on a grid of `n`
// voxels a side, `spacing` apart along the axes of `rotation`, centred on the origin.
render::UnderlayVolume linearVolume(int n, double spacing, const glm::dmat4& rotation) {
  render::UnderlayVolume v;
  v.name = "linear";
  v.dims[0] = v.dims[1] = v.dims[2] = n;
  const double half = 0.5 * (n - 1) * spacing;
  v.indexToWC = rotation * glm::translate(glm::dmat4(1.0), glm::dvec3(-half)) *
                glm::scale(glm::dmat4(1.0), glm::dvec3(spacing));
  v.values.resize(v.voxels());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const glm::dvec3 p(v.indexToWC * glm::dvec4(i, j, k, 1));
        v.values[std::size_t(i + n * (j + n * k))] = float(0.5 + 0.1 * p.x - 0.07 * p.y + 0.03 * p.z);
      }
  return v;
}

// One sphere of radius `r` at `centre`.
tensor::GlyphSet sphereAt(const glm::dvec3& centre, float r) {
  const float pos[3] = {float(centre.x), float(centre.y), float(centre.z)};
  const float ten[6] = {r, 0, 0, r, 0, r};
  return tensor::buildGlyphs(std::span(pos, 3), std::span(ten, 6), {});
}

class SlicePlanes : public GlFixture {
 protected:
  // `set` with one plane of `volume` (none when `spec` is null).
  render::FrameImage drawWith(const tensor::GlyphSet& set, const render::Camera& cam, const render::FrameParams& p,
                              const render::UnderlayVolume* volume, const render::PlaneSpec* spec,
                              const render::SliceParams& sp = {}) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    if (volume && spec) {
      auto shared = std::make_shared<const render::SliceVolume>(ctx_->api(), *lib_, *volume);
      r.addContext(std::make_unique<render::SlicePlane>(shared, *spec, sp, set.maxAbsEigenvalue));
    }
    r.render(cam, p, target);
    return r.readback(cam, target);
  }
};

render::Camera topCamera(int w, int h, render::Projection proj, double dist = 12, double height = 12) {
  render::CameraDesc d;
  d.eyeWC = {1.5, -dist / 6, height};
  d.lookAtWC = {0, 0, 0};
  d.projection = proj;
  d.fovYDeg = 40;
  d.orthoHeight = 10;
  return render::makeCamera(d, w, h, glm::dvec3(-8), glm::dvec3(8));
}

std::size_t countId(const render::FrameImage& img, std::uint32_t id) {
  return std::size_t(std::count(img.id.begin(), img.id.end(), id));
}

// The same world plane through the same world-linear function on two grids
// of different spacing (1 and 0.37) and orientation (the second turned 40
// degrees about (1, 2, 3)): wherever both cover a pixel, the plane shows the
// same value, because each is sampled through its own index-to-world map. A
// map that ignored the rotation is the control: it differs by far more.
// Tolerance 0.01: trilinear interpolation reproduces a linear function
// exactly; what remains is texture filtering's 8-bit weights (f changes by
// at most 0.13 per voxel of 0.37, so 0.0005) and the lit colour's rounding.
TEST_F(SlicePlanes, AnUnderlayOnAnotherGridLinesUpInWorldCoordinates) {
  const tensor::GlyphSet none = sphereAt({100, 100, 100}, 0.1f);
  const auto cam = topCamera(96, 72, render::Projection::Orthographic);
  const render::UnderlayVolume a = linearVolume(9, 1.0, glm::dmat4(1.0));
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(40.0), glm::normalize(glm::dvec3(1, 2, 3)));
  const render::UnderlayVolume b = linearVolume(40, 0.37, turn);
  render::UnderlayVolume unturned = b;
  unturned.indexToWC = glm::inverse(turn) * b.indexToWC;
  render::PlaneSpec plane;
  plane.axis = -1;
  plane.pointWC = {0, 0, 0.3};
  plane.normalWC = {0, 0, 1};
  render::SliceParams sp;
  sp.window = std::pair(0.0, 1.0);
  render::FrameParams p;
  const auto ia = drawWith(none, cam, p, &a, &plane, sp), ib = drawWith(none, cam, p, &b, &plane, sp),
             iu = drawWith(none, cam, p, &unturned, &plane, sp);
  std::size_t both = 0;
  double worst = 0, control = 0;
  for (std::size_t k = 0; k < ia.id.size(); ++k) {
    if (ia.id[k] != render::kContextIdBase || ib.id[k] != render::kContextIdBase) continue;
    // Inside the first grid's voxel centres: its outer half cell holds the edge value.
    const auto ray = cam.rayThroughPixel(double(k % std::size_t(cam.width)) + 0.5, double(k / std::size_t(cam.width)) + 0.5);
    const glm::dvec3 at = ray.origin + (0.3 - ray.origin.z) / ray.direction.z * ray.direction;
    if (std::abs(at.x) > 3.9 || std::abs(at.y) > 3.9) continue;
    ++both;
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, double(std::abs(ia.rgba[4 * k + c] - ib.rgba[4 * k + c])));
      if (iu.id[k] == render::kContextIdBase)
        control = std::max(control, double(std::abs(ia.rgba[4 * k + c] - iu.rgba[4 * k + c])));
    }
  }
  EXPECT_GT(both, 2000u);
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(control, 0.05);
  // The CPU sampler agrees across the grids too (picking reads it).
  for (const glm::dvec3 q : {glm::dvec3(0.3, -1.2, 0.3), glm::dvec3(-3.1, 2.2, 0.3), glm::dvec3(2.9, 3.3, -1.0)}) {
    const auto va = a.sample(q, true), vb = b.sample(q, true);
    ASSERT_TRUE(va && vb);
    EXPECT_NEAR(*va, 0.5 + 0.1 * q.x - 0.07 * q.y + 0.03 * q.z, 1e-6);
    EXPECT_NEAR(*va, *vb, 1e-6);
  }
}

// A glyph centred on the plane is whole with the default offset (one largest
// glyph radius); at offset 0 the plane cuts away the part below it that a
// low view sees; a glyph
// three radii behind the plane is hidden by it.
TEST_F(SlicePlanes, GlyphsOnThePlaneAreWholeAndThoseBehindItHidden) {
  // Low, so that the view sees below the glyph's equator.
  const auto cam = topCamera(120, 90, render::Projection::Perspective, 30, 6);
  const render::UnderlayVolume v = linearVolume(17, 0.5, glm::dmat4(1.0));
  render::PlaneSpec mid;  // z:8 is z = 0
  mid.axis = 2;
  mid.index = 8;
  render::FrameParams p;
  const auto onPlane = sphereAt({0, 0, 0}, 1.0f);
  const std::size_t alone = countId(drawWith(onPlane, cam, p, nullptr, nullptr), 0);
  ASSERT_GT(alone, 300u);
  const std::size_t offset = countId(drawWith(onPlane, cam, p, &v, &mid), 0);
  EXPECT_GE(double(offset), 0.995 * double(alone));
  render::SliceParams trueDepth;
  trueDepth.depthOffsetRadii = 0;
  const std::size_t cut = countId(drawWith(onPlane, cam, p, &v, &mid, trueDepth), 0);
  EXPECT_LT(double(cut), 0.95 * double(alone));  // about sin(11 deg) of the disc lies below the plane
  const auto behind = sphereAt({0, 0, -3}, 1.0f);
  ASSERT_GT(countId(drawWith(behind, cam, p, nullptr, nullptr), 0), 100u);
  EXPECT_EQ(countId(drawWith(behind, cam, p, &v, &mid), 0), 0u);
}

// The viewer moves a plane by setSpec, which computes a new quad on the CPU
// and touches no GL object: the moved plane draws exactly as one made at its
// new index, the renderer holds the same GPU memory, an index outside the
// grid leaves it where it was, and a hidden plane draws nothing.
TEST_F(SlicePlanes, AMovedPlaneDrawsAsOneMadeThereAndAHiddenOneNotAtAll) {
  const tensor::GlyphSet none = sphereAt({100, 100, 100}, 0.1f);
  const auto cam = topCamera(96, 72, render::Projection::Perspective);
  const render::UnderlayVolume v = linearVolume(9, 1.0, glm::dmat4(1.0));
  render::PlaneSpec from, to, outside;
  from.axis = to.axis = outside.axis = 2;
  from.index = 1;
  to.index = 6;
  outside.index = 9;
  render::FrameParams p;
  const auto want = drawWith(none, cam, p, &v, &to);
  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(none);
  auto shared = std::make_shared<const render::SliceVolume>(ctx_->api(), *lib_, v);
  auto& plane = static_cast<render::SlicePlane&>(
      r.addContext(std::make_unique<render::SlicePlane>(shared, from, render::SliceParams{}, none.maxAbsEigenvalue)));
  r.render(cam, p, target);
  const auto before = r.readback(cam, target);
  const std::size_t bytes = r.gpuBytes();
  plane.setSpec(to);
  r.render(cam, p, target);
  const auto moved = r.readback(cam, target);
  EXPECT_GT(countId(moved, render::kContextIdBase), 2000u);
  EXPECT_EQ(moved.rgba, want.rgba);
  EXPECT_EQ(moved.depth, want.depth);
  EXPECT_NE(moved.depth, before.depth);
  EXPECT_EQ(r.gpuBytes(), bytes);
  EXPECT_THROW(plane.setSpec(outside), std::invalid_argument);
  EXPECT_EQ(plane.spec(), to);
  plane.setVisible(false);
  r.render(cam, p, target);
  EXPECT_EQ(countId(r.readback(cam, target), render::kContextIdBase), 0u);
}

// A masked field's own FA keeps only a thin structure; every other voxel is
// a hole. Linear filtering next to a hole takes the nearest voxel, so a row
// one voxel thick is drawn (it used to vanish: a NaN among the 8 texels made
// every sample NaN) exactly where nearest sampling draws it, and the CPU
// sampler, which picking reads, agrees.
TEST_F(SlicePlanes, AOneVoxelRowAmongHolesIsDrawnWithLinearFiltering) {
  const tensor::GlyphSet none = sphereAt({100, 100, 100}, 0.1f);
  const auto cam = topCamera(96, 72, render::Projection::Orthographic);
  render::UnderlayVolume v = linearVolume(9, 1.0, glm::dmat4(1.0));
  for (std::size_t k = 0; k < v.values.size(); ++k)
    if (k / 9 != 4 + 9 * 4) v.values[k] = NAN;  // keeps the row j = 4, k = 4 (y = 0, z = 0)
  render::PlaneSpec mid;
  mid.axis = 2;
  mid.index = 4;
  render::SliceParams nearest;
  nearest.linear = false;
  render::FrameParams p;
  const auto linear = drawWith(none, cam, p, &v, &mid), near = drawWith(none, cam, p, &v, &mid, nearest);
  EXPECT_GT(countId(linear, render::kContextIdBase), 50u);
  EXPECT_EQ(linear.id, near.id);
  const auto at = v.sample({1.2, 0.3, 0.0}, true);
  ASSERT_TRUE(at);
  EXPECT_EQ(*at, *v.sample({1.2, 0.3, 0.0}, false));
  EXPECT_FALSE(v.sample({1.2, 0.7, 0.0}, true));
}

// A window as wide as single precision holds (a volume of +-3e38, whose
// percentiles span it) maps as a narrow one does: its width overflowed a
// float, and the whole plane drew black.
TEST_F(SlicePlanes, AWindowAsWideAsFloatsHoldMapsAsANarrowOne) {
  const tensor::GlyphSet none = sphereAt({100, 100, 100}, 0.1f);
  const auto cam = topCamera(96, 72, render::Projection::Orthographic);
  render::UnderlayVolume v = linearVolume(9, 1.0, glm::dmat4(1.0));
  for (std::size_t k = 0; k < v.values.size(); ++k) v.values[k] = float(k % 3) - 1.0f;  // -1, 0, 1 along x
  render::UnderlayVolume wide = v;
  for (float& x : wide.values) x *= 3e38f;
  render::PlaneSpec mid;
  mid.axis = 2;
  mid.index = 4;
  render::SliceParams narrow, full;
  narrow.linear = full.linear = false;
  narrow.window = std::pair(-1.0, 1.0);
  full.window = std::pair(-3e38, 3e38);
  render::FrameParams p;
  const auto a = drawWith(none, cam, p, &v, &mid, narrow), b = drawWith(none, cam, p, &wide, &mid, full);
  ASSERT_GT(countId(a, render::kContextIdBase), 1000u);
  EXPECT_EQ(a.id, b.id);
  float worst = 0;
  for (std::size_t k = 0; k < a.rgba.size(); ++k) worst = std::max(worst, std::abs(a.rgba[k] - b.rgba[k]));
  EXPECT_LT(worst, 1e-3f);
}

// Depth mixing: an elongated glyph half through an oblique plane, against
// the reference's ellipsoid and plane (coverage, ids, depth, normals), at
// true depth and with the offset. Tolerances as the ellipsoid tests': the
// plane's edge and the glyph's silhouette may round a pixel either way.
TEST_F(SlicePlanes, AGlyphHalfThroughAPlaneMatchesTheReference) {
  const float pos[3] = {0.2f, -0.1f, 0.0f};
  const float ten[6] = {2.5f, 0.8f, 0.9f, 1.0f, 0.2f, 1.4f};
  const auto set = tensor::buildGlyphs(std::span(pos, 3), std::span(ten, 6), {});
  const render::UnderlayVolume v = linearVolume(21, 0.5, glm::dmat4(1.0));
  render::PlaneSpec plane;
  plane.axis = -1;
  plane.pointWC = {0, 0, 0.2};
  plane.normalWC = {0.2, -0.3, 1.0};
  for (auto proj : {render::Projection::Perspective, render::Projection::Orthographic})
    for (double radii : {0.0, 0.5}) {
      SCOPED_TRACE(radii);
      const auto cam = topCamera(160, 120, proj);
      render::SliceParams sp;
      sp.depthOffsetRadii = radii;
      render::FrameParams p;
      const auto gpu = drawWith(set, cam, p, &v, &plane, sp);
      ref::RefImage want = ref::renderEllipsoids(cam, set.glyphs, {1.0});
      const double offsetWC = radii * tensor::glyphRadiusWC(1.0, {}, set.maxAbsEigenvalue);
      ref::addPlane(want, cam, render::planeQuad(v, plane), render::kContextIdBase, offsetWC, &v);
      const auto c = compare(gpu, want, cam);
      std::size_t glyphPixels = 0, planePixels = 0;
      for (std::uint32_t id : want.id) (id == 0 ? glyphPixels : planePixels) += id == 0 || id == render::kContextIdBase;
      EXPECT_GT(glyphPixels, 500u);
      EXPECT_GT(planePixels, 2000u);
      expectWithin(c, {0.002, 0.02, 0.002, 1e-4, 0.05, 2.0}, "plane and glyph");
    }
}

// Small golden image: helix glyphs over their own FA-like underlay in viridis,
// with shadows. Max 40/255 and mean 0.6/255, as the shadow goldens and for
// the same reasons (a PCF texel rounding either way on another llvmpipe).
TEST_F(SlicePlanes, GoldenImage) {
  const auto helix = synth::helixPhantom(10, 10, 4);
  const auto set = glyphsOf(helix.field);
  const glm::dvec3 c = 0.5 * (set.boundsMinWC + set.boundsMaxWC);
  const double size = glm::length(set.boundsMaxWC - set.boundsMinWC);
  const render::UnderlayVolume v =
      linearVolume(24, size / 20, glm::translate(glm::dmat4(1.0), c) * glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(0, 0, 1)));
  render::CameraDesc d;
  d.lookAtWC = c;
  d.eyeWC = c + size * glm::dvec3(0.3, -0.6, 0.9);
  d.fovYDeg = 45;
  const auto cam = render::makeCamera(d, 128, 96, c - size, c + size);
  render::PlaneSpec plane;
  plane.axis = -1;
  plane.pointWC = c;
  plane.normalWC = {0, 0, 1};
  render::SliceParams sp;
  sp.colormap = render::Colormap::Viridis;
  render::FrameParams p;
  p.scale = tensor::defaultScale(set, helix.field.sampleSpacing);
  p.shadow.enabled = true;
  const auto img = drawWith(set, cam, p, &v, &plane, sp);
  test::expectMatchesGolden(img, "slice-plane", 40, 0.6);
}

}  // namespace
}  // namespace tg::test
