// Tier 3: the compute glyph path's own machinery (render/compute_glyphs.h)
// on llvmpipe: tile lists that grow, records in chunks, the batch cull,
// crowded tiles of many sorted runs, its refusals and which visibility
// buffer it takes; its pictures against the raster path's with the
// tolerances of cast_agreement.h (CastPaths in test_cpu_glyphs.cpp draws the
// reference scenes).
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>

#include "cast_agreement.h"
#include "io/core/readers.h"
#include "real_data.h"
#include "render/compute_glyphs.h"
#include "render_fixture.h"

using namespace tg;
using namespace tg::test;

using ComputeGlyphs = GlFixture;

// Tile lists that start too small for the frame (4 glyphs, 16 entries):
// the frame is cast again with room, and matches the raster path.
TEST_F(ComputeGlyphs, ListsTooSmallForAFrameGrowAndTheFrameMatches) {
  const tensor::GlyphSet set = grid(4, 7);
  const double scale = 0.45;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 9.0, render::Projection::Perspective), 200, 150);
  render::FrameParams p = test::superquadricParams(scale, 3.0);
  ctx_->makeCurrent();
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  render::GlyphRenderer r(ctx_->api(), *lib_, nullptr, std::make_unique<render::ComputeGlyphs>(ctx_->api(), *lib_, 4, 16));
  r.upload(set);
  const std::size_t before = r.glyphPath().gpuBytes();
  r.render(cam, p, target);
  EXPECT_GT(r.glyphPath().gpuBytes(), before + 16 * 80) << "the lists did not grow";
  Pair s;
  s.cpu = r.readback(cam, target);
  render::GlyphRenderer raster(ctx_->api(), *lib_, nullptr, "raster");
  raster.upload(set);
  raster.render(cam, p, target);
  s.raster = raster.readback(cam, target);
  expectAgree(s, cam, "lists grown", 500, true);
}

// Records past one storage block are held in chunks (at 10^8 glyphs, 4.8 GB
// against a block of 2^31 bytes or less); chunks of 7 records draw the
// picture of one chunk exactly, in every cast class, with colour scalars
// and the sign colour's GC hits taken per chunk.
TEST_F(ComputeGlyphs, RecordsInChunksDrawTheOneChunkPicture) {
  const tensor::GlyphSet set = grid(4, 7);
  const double scale = 0.45;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 9.0, render::Projection::Perspective), 160, 120);
  ctx_->makeCurrent();
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  auto chunked = std::make_unique<render::ComputeGlyphs>(ctx_->api(), *lib_, 1 << 16, 1 << 18, 7);
  const render::ComputeGlyphs* path = chunked.get();
  render::GlyphRenderer split(ctx_->api(), *lib_, nullptr, std::move(chunked));
  render::GlyphRenderer whole(ctx_->api(), *lib_, nullptr, "compute");
  std::vector<float> scalars(set.glyphs.size());
  for (std::size_t k = 0; k < scalars.size(); ++k) scalars[k] = float(k % 11);
  for (render::GlyphRenderer* r : {&split, &whole}) {
    r->upload(set);
    r->setColorScalars(scalars, "k mod 11");
  }
  EXPECT_EQ(path->recordChunks(), (set.glyphs.size() + 6) / 7);
  EXPECT_EQ(path->recordBuffer(), 0u) << "several chunks have no one buffer";
  EXPECT_NE(whole.glyphPath().recordBuffer(), 0u);
  struct Case {
    render::GlyphKind glyph;
    render::ColorMode color;
  };
  for (const Case c : {Case{render::GlyphKind::Ellipsoid, render::ColorMode::Array},
                       Case{render::GlyphKind::Superquadric, render::ColorMode::Sign},
                       Case{render::GlyphKind::Cylinder, render::ColorMode::FA},
                       Case{render::GlyphKind::Box, render::ColorMode::Array}}) {
    render::FrameParams p = test::superquadricParams(scale, 3.0);
    p.glyph = c.glyph;
    p.color = c.color;
    p.shadow.enabled = c.glyph == render::GlyphKind::Superquadric;
    split.render(cam, p, target);
    const render::FrameImage a = split.readback(cam, target);
    whole.render(cam, p, target);
    const render::FrameImage b = whole.readback(cam, target);
    SCOPED_TRACE(std::string(render::glyphKind(c.glyph).name));
    EXPECT_GT(std::count_if(a.id.begin(), a.id.end(), [](std::uint32_t id) { return id != ref::kNoGlyph; }), 500);
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.normalWC, b.normalWC);
    EXPECT_EQ(a.rgba, b.rgba);
  }
}

// Batches of 8,192 records are culled each frame against the side planes,
// the FA threshold and the slab: a 32^3 grid is 4 batches of 8 z-layers. A
// narrow view of the bottom layers keeps fewer, a slab of them one and a
// threshold above every FA none, and each frame is the raster path's.
TEST_F(ComputeGlyphs, BatchesOutOfViewOrSelectionAreCulled) {
  const tensor::GlyphSet set = grid(32, 5);
  ASSERT_EQ(set.glyphs.size(), 4 * render::kBatchRecords);
  const double scale = 0.4;
  ctx_->makeCurrent();
  render::CameraDesc d;
  d.lookAtWC = {15.5, 15.5, 2.0};
  d.eyeWC = {15.5, -60.0, 2.0};
  d.upWC = {0, 0, 1};
  d.fovYDeg = 6.0;
  const auto cam = test::cameraFor(set, scale, d, 160, 120);
  auto owned = std::make_unique<render::ComputeGlyphs>(ctx_->api(), *lib_);
  const render::ComputeGlyphs* path = owned.get();
  render::GlyphRenderer r(ctx_->api(), *lib_, nullptr, std::move(owned));
  render::GlyphRenderer raster(ctx_->api(), *lib_, nullptr, "raster");
  r.upload(set);
  raster.upload(set);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  const std::uint64_t passes = path->atomics64() ? 1 : 2;
  auto frame = [&](const render::FrameParams& p, const std::string& what, std::size_t minCovered) {
    r.render(cam, p, target);
    Pair s;
    s.cpu = r.readback(cam, target);
    raster.render(cam, p, target);
    s.raster = raster.readback(cam, target);
    if (minCovered > 0) expectAgree(s, cam, what, minCovered);
    else EXPECT_EQ(s.raster.id, s.cpu.id) << what;
    return path->batchesKept();
  };
  render::FrameParams p;
  p.scale = scale;
  // The view's height at the grid is about 8 layers: the bottom batch, and
  // its neighbour within a glyph's reach of the edge.
  const std::uint64_t narrow = frame(p, "narrow view", 2000);
  EXPECT_GE(narrow, passes);
  EXPECT_LE(narrow, 2 * passes);
  p.slab = {2, 0.0, 3.0};
  EXPECT_EQ(frame(p, "slab of the bottom layers", 2000), passes);
  p.slab = {};
  p.faMin = 1.0;  // the grid's positive-definite FAs are below 1; mixed signs may pass it
  const auto aboveOne = std::count_if(set.glyphs.begin(), set.glyphs.end(), [](const auto& g) { return g.fa >= 1.0f; });
  frame(p, "FA threshold 1", aboveOne > 0 ? 1 : 0);
  p.faMin = 1e3;
  EXPECT_EQ(frame(p, "FA threshold above all", 0), 0u);
  EXPECT_EQ(r.drawnGlyphs(), 0u);
  // The whole grid in view keeps every batch.
  const auto whole = test::cameraFor(set, scale, test::oblique(set, 70.0, render::Projection::Perspective), 160, 120);
  render::FrameParams all;
  all.scale = scale;
  r.render(whole, all, target);
  EXPECT_EQ(path->batchesKept(), 4 * passes);
}

// Tiles whose lists hold many sorted runs of 1,024 (compute_sort.comp):
// Kindlmann's dt-helix at 100 times its default scale, all 59,280 glyphs
// over every tile of a 64x48 frame and most around the eye. Cast front to
// back per run, the frame is the raster path's exactly, frame after frame
// (runs sorted wrongly lost whole tiles' pixels, differently each frame).
TEST_F(ComputeGlyphs, CrowdedTilesOfManySortedRunsMatchTheRasterPath) {
  TG_REQUIRE_REAL_DATA();
  const tensor::GlyphSet set = test::glyphsOf(io::readTensorField(test::realData("kindlmann-dt-helix/dt-helix.nhdr"), {}));
  const double scale = 5.5;
  const auto cam = test::cameraFor(set, 0.06, test::oblique(set, 8.0, render::Projection::Perspective), 64, 48);
  ctx_->makeCurrent();
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  render::GlyphRenderer raster(ctx_->api(), *lib_, nullptr, "raster");
  render::GlyphRenderer compute(ctx_->api(), *lib_, nullptr, "compute");
  raster.upload(set);
  compute.upload(set);
  render::FrameParams p;
  p.scale = scale;
  raster.render(cam, p, target);
  const render::FrameImage want = raster.readback(cam, target);
  const auto covered = std::count_if(want.id.begin(), want.id.end(), [](std::uint32_t id) { return id != ref::kNoGlyph; });
  EXPECT_GT(covered, 1000);
  for (int k = 0; k < 2; ++k) {
    compute.render(cam, p, target);
    const render::FrameImage got = compute.readback(cam, target);
    EXPECT_EQ(got.depth, want.depth) << "frame " << k;
    // Spheres' walls crossing at a pixel centre tie in depth, and the paths
    // may keep either (kDepthTies); no pixel is lost or another glyph's.
    std::size_t ties = 0;
    for (std::size_t i = 0; i < want.id.size(); ++i)
      if (got.id[i] != want.id[i]) {
        EXPECT_NE(got.id[i], ref::kNoGlyph) << "frame " << k << ", pixel " << i;
        EXPECT_EQ(got.depth[i], want.depth[i]) << "frame " << k << ", pixel " << i;
        ++ties;
      }
    std::printf("[ compute ] crowded tiles, frame %d: %zu of %td covered pixels tie\n", k, ties, covered);
    EXPECT_LE(double(ties), kDepthTies * double(covered)) << "frame " << k;
  }
}

TEST_F(ComputeGlyphs, BlobsAreRefusedNamingTheCpuPath) {
  const tensor::GlyphSet set = grid(2, 3);
  ctx_->makeCurrent();
  const auto cam = test::cameraFor(set, 0.5, test::oblique(set, 5.0, render::Projection::Perspective), 64, 48);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  render::GlyphRenderer r(ctx_->api(), *lib_, nullptr, "compute");
  r.upload(set);
  render::FrameParams p;
  p.scale = 0.5;
  p.glyph = render::GlyphKind::Blob;
  try {
    r.render(cam, p, target);
    ADD_FAILURE() << "the compute path drew blobs";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("casts no blobs; use the cpu path"), std::string::npos) << e.what();
  }
}

// Which visibility buffer the path writes follows the GL's extensions; the
// ctest entry ComputeGlyphs.Atomics64OnLlvmpipe runs the compute tests again
// with llvmpipe's 64-bit atomics switched on (MESA_EXTENSION_OVERRIDE) and
// TG_TEST_EXPECT_ATOMICS64=1, so that both variants are tested here.
TEST_F(ComputeGlyphs, VisibilityBufferFollowsTheGlsAtomics) {
  ctx_->makeCurrent();
  const render::ComputeGlyphs path(ctx_->api(), *lib_);
  bool nv = false;
  GLint n = 0;
  ctx_->api().GetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (GLint k = 0; k < n; ++k) {
    const auto* e = reinterpret_cast<const char*>(ctx_->api().GetStringi(GL_EXTENSIONS, GLuint(k)));
    nv = nv || std::string(e) == "GL_NV_shader_atomic_int64";
  }
  EXPECT_EQ(path.atomics64(), nv);
  if (const char* want = std::getenv("TG_TEST_EXPECT_ATOMICS64")) {
    EXPECT_EQ(path.atomics64(), std::string(want) == "1");
  }
  EXPECT_NE(path.how().find(path.atomics64() ? "64-bit atomics" : "two passes of 32-bit atomics"), std::string::npos);
}
