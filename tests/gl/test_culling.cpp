// Tier 3: culling (render/glyph_culling.h) changes what a frame costs, never
// what it shows. Exact equality is the right bound here: culled and unculled
// frames draw the same glyphs in the same order with the same shaders.
#include "render/raster_glyphs.h"
#include "render_fixture.h"

#include <algorithm>
#include <random>
#include <vector>

#include "data-synthetic/generators.h"

using namespace tg;
using test::GlFixture;

namespace {

struct Frame {
  render::FrameImage img;
  std::uint64_t drawn;
  render::GlyphCulling::Passes passes;
  bool indirect;
};

// The glyphs of `f` that `pred` keeps, with their input ids.
template <class Pred>
tensor::GlyphSet keptOnly(const io::TensorField& f, Pred pred) {
  const auto all = test::glyphsOf(f);
  std::vector<bool> keep(f.ids.empty() ? all.glyphs.size() : f.ids.size(), false);
  for (const auto& g : all.glyphs) keep[g.id] = pred(g);
  std::vector<float> pos, ten;
  std::vector<std::uint32_t> ids;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    if (!keep[i]) continue;
    pos.insert(pos.end(), &f.positions[3 * i], &f.positions[3 * i] + 3);
    ten.insert(ten.end(), &f.tensors[6 * i], &f.tensors[6 * i] + 6);
    ids.push_back(std::uint32_t(i));
  }
  return tensor::buildGlyphs(pos, ten, ids);
}

// Every dispatch group on a 14^3 grid: each 7th tensor a sphere, each 3rd
// shifted to be definite, the rest random with mixed signs.
io::TensorField allGroups() {
  io::TensorField f;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::uint32_t i = 0; i < 14 * 14 * 14; ++i) {
    const double shift = i % 3 == 0 ? 2.5 : 0.0, iso = u(rng);
    double t[9] = {shift + u(rng), u(rng), u(rng), 0, shift + u(rng), u(rng), 0, 0, shift + u(rng)};
    if (i % 7 == 0) t[0] = t[4] = t[8] = iso, t[1] = t[2] = t[5] = 0;
    t[3] = t[1], t[6] = t[2], t[7] = t[5];
    const double p[3] = {double(i % 14), double(i / 14 % 14), double(i / 196)};
    f.addFull(i, p, t);
  }
  return f;
}

std::size_t differing(const render::FrameImage& a, const render::FrameImage& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.id.size(); ++i) n += a.id[i] != b.id[i] || a.rgba[4 * i] != b.rgba[4 * i];
  return n;
}

class Culling : public GlFixture {
 protected:
  // Renders `frames` frames of one upload with `p`, the last one read back.
  Frame frames(const tensor::GlyphSet& set, const render::Camera& cam, std::vector<render::FrameParams> ps) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    for (const auto& p : ps) r.render(cam, p, target);
    return {r.readback(cam, target), r.drawnGlyphs(), render::asRaster(r.glyphPath()).culling().passes(), render::asRaster(r.glyphPath()).culling().indirect()};
  }
};

}  // namespace

TEST_F(Culling, ThresholdDrawsExactlyTheKeptGlyphs) {
  // All three dispatch groups, so that every split is tested.
  const io::TensorField field = allGroups();
  const auto set = test::glyphsOf(field);
  ASSERT_GT(set.sphereCount, 0u);
  ASSERT_GT(set.definiteCount, 0u);
  ASSERT_GT(set.glyphs.size(), set.sphereCount + set.definiteCount);
  std::vector<float> fa;
  for (const auto& g : set.glyphs) fa.push_back(g.fa);
  std::nth_element(fa.begin(), fa.begin() + std::ptrdiff_t(fa.size() / 2), fa.end());
  const float t = fa[fa.size() / 2];
  const auto kept = keptOnly(field, [&](const tensor::GlyphRecord& g) { return g.fa >= t; });
  ASSERT_GT(kept.glyphs.size(), 0u);
  ASSERT_LT(kept.glyphs.size(), set.glyphs.size());

  const double scale = 0.5 / set.maxAbsEigenvalue;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 60.0, render::Projection::Perspective), 240, 180);
  for (const auto& [kind, gamma] : {std::pair{render::GlyphKind::Ellipsoid, 3.0},
                                    std::pair{render::GlyphKind::Superquadric, 3.0},
                                    std::pair{render::GlyphKind::Superquadric, 0.0}}) {
    SCOPED_TRACE(gamma);
    render::FrameParams p;
    p.scale = scale;
    p.glyph = kind;
    p.gamma = gamma;
    const Frame whole = frames(kept, cam, {p});
    p.faMin = t;
    const Frame culled = frames(set, cam, {p});
    EXPECT_EQ(culled.drawn, kept.glyphs.size());
    EXPECT_EQ(whole.drawn, kept.glyphs.size());
    EXPECT_TRUE(culled.indirect);
    EXPECT_FALSE(whole.indirect);
    EXPECT_EQ(differing(culled.img, whole.img), 0u);
    std::size_t covered = 0;
    for (auto id : culled.img.id) covered += id != ref::kNoGlyph;
    EXPECT_GT(covered, 400u);
  }
}

TEST_F(Culling, CompactionRunsOncePerThresholdChange) {
  const auto set = test::glyphsOf(synth::randomField(3000, 4));
  // Far enough that the scene's box, grown by the largest glyph, is in view.
  const auto cam = test::cameraFor(set, 0.5, test::oblique(set, 90.0, render::Projection::Perspective), 64, 48);
  render::FrameParams a, b, off;
  a.scale = b.scale = off.scale = 0.5;
  a.faMin = 0.4;
  b.faMin = 0.5;
  // Glyphs of a pixel or two: on llvmpipe the per-frame pixel cull would
  // apply the threshold instead (test_pixel_cull.cpp), as it never does on a GPU.
  a.pixelCull = b.pixelCull = off.pixelCull = false;
  EXPECT_EQ(frames(set, cam, {a, a, a}).passes.compactions, 1u);
  EXPECT_EQ(frames(set, cam, {a, b, b, a}).passes.compactions, 3u);
  // A threshold that hides nothing, with the whole scene in view: no pass at all.
  const Frame f = frames(set, cam, {a, off});
  EXPECT_FALSE(f.indirect);
  EXPECT_EQ(f.passes.commandPasses, 1u);  // only the first frame's
  EXPECT_EQ(f.drawn, set.glyphs.size());
  // A tessellated frame after a culled one draws, and reports, every glyph.
  render::FrameParams mesh = off;
  mesh.glyph = render::GlyphKind::Superquadric;
  mesh.tessellation = 4;
  const Frame t = frames(set, cam, {a, mesh});
  EXPECT_FALSE(t.indirect);
  EXPECT_EQ(t.drawn, set.glyphs.size());
}

TEST_F(Culling, FrustumCullingChangesOnlyTheWork) {
  const auto set = test::glyphsOf(synth::randomField(20000, 9));
  const double scale = 0.5;
  // Along y near the x = z = 0 edge of the 28^3 grid: a tile is about 9
  // rows of one z slice, and the view meets only the lowest slices' tiles.
  render::CameraDesc d;
  d.eyeWC = {2, -10, 2};
  d.lookAtWC = {2, 0, 2};
  d.upWC = {0, 0, 1};
  d.fovYDeg = 20;
  const auto cam = test::cameraFor(set, scale, d, 160, 120);
  for (double faMin : {0.0, 0.3}) {
    SCOPED_TRACE(faMin);
    render::FrameParams p;
    p.scale = scale;
    p.faMin = faMin;
    const Frame culled = frames(set, cam, {p});
    p.frustumCulling = false;
    const Frame all = frames(set, cam, {p});
    EXPECT_EQ(differing(culled.img, all.img), 0u);
    EXPECT_TRUE(culled.indirect);
    EXPECT_LT(culled.drawn * 2, all.drawn);  // most glyphs culled
    EXPECT_GT(culled.drawn, 0u);
    std::size_t covered = 0;
    for (auto id : culled.img.id) covered += id != ref::kNoGlyph;
    EXPECT_GT(covered, 3000u);
  }
}

TEST_F(Culling, SlabShowsExactlyTheGlyphsWhoseCentresItHolds) {
  const io::TensorField field = allGroups();
  const auto set = test::glyphsOf(field);
  const double scale = 0.5 / set.maxAbsEigenvalue;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 60.0, render::Projection::Perspective), 240, 180);
  for (int axis : {0, 2}) {
    SCOPED_TRACE(axis);
    const auto kept = keptOnly(field, [&](const tensor::GlyphRecord& g) {
      return g.posWC[axis] >= 4.5f && g.posWC[axis] <= 6.5f;
    });
    render::FrameParams p = test::superquadricParams(scale);
    const Frame whole = frames(kept, cam, {p});
    p.slab = {axis, 4.5, 6.5};
    const Frame slab = frames(set, cam, {p});
    EXPECT_EQ(differing(slab.img, whole.img), 0u);
    EXPECT_GE(slab.drawn, kept.glyphs.size());
    // Tiles are rows of one z slice: a z slab skips whole tiles, an x slab
    // leaves the culling to the vertex stage.
    if (axis == 2) {
      EXPECT_LT(slab.drawn, set.glyphs.size() / 2);
    }
    std::size_t covered = 0;
    for (auto id : slab.img.id) covered += id != ref::kNoGlyph;
    EXPECT_GT(covered, 400u);
  }
}

// setParams updates only the uniforms that changed: a frame after a chain of
// single changes must equal a fresh renderer's frame of the final parameters.
TEST_F(Culling, ChangesOneAtATimeEndWhereAFreshStartDoes) {
  const auto set = test::glyphsOf(allGroups());
  const double scale = 0.5 / set.maxAbsEigenvalue;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 60.0, render::Projection::Perspective), 160, 120);
  std::vector<render::FrameParams> chain(1);
  chain[0].scale = scale;
  auto next = [&](auto edit) {
    chain.push_back(chain.back());
    edit(chain.back());
  };
  next([](auto& p) { p.glyph = render::GlyphKind::Superquadric; });
  next([](auto& p) { p.gamma = 1.5; });
  next([](auto& p) { p.faMin = 0.2; });
  next([](auto& p) { p.scale *= 1.3; });
  next([](auto& p) { p.color = render::ColorMode::FA; });
  next([](auto& p) { p.slab = {2, 3.0, 9.0}; });
  next([](auto& p) { p.march.maxIterations = 6; });
  next([](auto& p) { p.light.ambient = 0.5f; });
  next([](auto& p) { p.background = {0.2f, 0.1f, 0.0f, 1.0f}; });
  const Frame chained = frames(set, cam, chain);
  const Frame fresh = frames(set, cam, {chain.back()});
  EXPECT_EQ(differing(chained.img, fresh.img), 0u);
  // and each step mattered: the first frame differs from the last.
  const Frame first = frames(set, cam, {chain.front()});
  EXPECT_GT(differing(first.img, fresh.img), 1000u);
}

// The viewer's status count never waits for the GPU, yet once a frame has
// finished it reports exactly what the blocking count does, frame after frame
// and in request order (culled frames through a fenced copy, direct frames
// from the CPU).
TEST_F(Culling, DrawnCountWithoutWaitingCatchesUpInOrder) {
  const auto set = test::glyphsOf(synth::randomField(3000, 4));
  const double scale = 0.5 / set.maxAbsEigenvalue;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 60.0, render::Projection::Perspective), 160, 120);
  ctx_->makeCurrent();
  const gl::Api& gl = ctx_->api();
  render::GlyphRenderer r(gl, *lib_);
  render::GBuffer target(gl, cam.width, cam.height);
  r.upload(set);
  EXPECT_FALSE(r.latestDrawnCount().has_value());
  auto renderAndRequest = [&](double faMin) {
    render::FrameParams p;
    p.scale = scale;
    p.faMin = faMin;
    r.render(cam, p, target);
    r.requestDrawnCount();
  };
  std::vector<std::uint64_t> blocking;
  for (double faMin : {0.0, 0.3, 0.6, 0.0, 0.8}) {
    renderAndRequest(faMin);
    gl.Finish();
    blocking.push_back(r.drawnGlyphs());
    EXPECT_EQ(r.latestDrawnCount(), blocking.back()) << "fa " << faMin;
  }
  EXPECT_EQ(blocking[0], set.glyphs.size());
  EXPECT_LT(blocking[4], blocking[2]);
  EXPECT_LT(blocking[2], blocking[1]);
  // Several frames in flight, then one finish: the newest wins, never an older one.
  for (double faMin : {0.3, 0.6, 0.8}) renderAndRequest(faMin);
  gl.Finish();
  EXPECT_EQ(r.latestDrawnCount(), blocking[4]);
}
