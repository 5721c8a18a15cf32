// Tier 3: the glyph paths that cast rays outside GL's rasteriser, the CPU
// path (render/cpu_glyphs.h) and the compute path (render/compute_glyphs.h),
// against the raster path on reference scenes (CastPaths, once per path),
// with the tolerances cast_agreement.h states; the CPU path's blobs.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

#include "data-synthetic/generators.h"
#include "cpu_frame.h"
#include "render/cpu_blobs.h"
#include "render/cpu_glyphs.h"
#include "render/pixel_probe.h"
#include "tensor/glyph_scale.h"
#include "thin_glyphs.h"
#include "cast_agreement.h"
#include "render_fixture.h"

using namespace tg;
using namespace tg::test;

namespace {

// Isotropic tensors only: every glyph a sphere.
tensor::GlyphSet spheres() {
  std::vector<float> pos, ten;
  for (int i = 0; i < 27; ++i) {
    const float r = 0.3f + 0.05f * float(i % 7);
    pos.insert(pos.end(), {float(i % 3), float(i / 3 % 3), float(i / 9) * 0.8f});
    ten.insert(ten.end(), {r, 0, 0, r, 0, r});
  }
  return tensor::buildGlyphs(pos, ten, {});
}

}  // namespace

class CastPaths : public GlFixture, public ::testing::WithParamInterface<std::string> {
 protected:
  // The raster path's frame and the frame of the path under test.
  Pair both(const tensor::GlyphSet& set, const render::Camera& cam, const render::FrameParams& p) {
    ctx_->makeCurrent();
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    Pair out;
    for (const std::string& path : {std::string("raster"), GetParam()}) {
      render::GlyphRenderer r(ctx_->api(), *lib_, nullptr, path);
      r.upload(set);
      r.render(cam, p, target);
      (path == "raster" ? out.raster : out.cpu) = r.readback(cam, target);
      if (path != "raster") out.cpuDrawn = r.drawnGlyphs();
    }
    return out;
  }
};

INSTANTIATE_TEST_SUITE_P(Paths, CastPaths, ::testing::Values("cpu", "compute"),
                         [](const ::testing::TestParamInfo<std::string>& param) { return param.param; });

using CpuGlyphs = GlFixture;

TEST_P(CastPaths, EllipsoidsMatchTheRasterPath) {
  const tensor::GlyphSet set = grid(4, 7);
  const double scale = 0.45;
  for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
    const auto cam = test::cameraFor(set, scale, test::oblique(set, 9.0, proj), 200, 150);
    render::FrameParams p;
    p.scale = scale;
    const Pair s = both(set, cam, p);
    expectAgree(s, cam, proj == render::Projection::Perspective ? "perspective" : "orthographic");
    EXPECT_GT(s.cpuDrawn, 20u);
  }
}

TEST_P(CastPaths, SpheresMatchTheRasterPath) {
  const tensor::GlyphSet set = spheres();
  const auto cam = test::cameraFor(set, 1.0, test::oblique(set, 6.0, render::Projection::Perspective), 160, 120);
  expectAgree(both(set, cam, render::FrameParams{}), cam, "spheres");
}

// Every colour mode (sign colours per surface point) and the selection: FA
// threshold and a slab.
TEST_P(CastPaths, ColoursAndSelectionMatchTheRasterPath) {
  const tensor::GlyphSet set = grid(4, 11);
  const double scale = 0.45;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 9.0, render::Projection::Perspective), 160, 120);
  for (const auto mode : {render::ColorMode::FA, render::ColorMode::MD, render::ColorMode::CL, render::ColorMode::Sign}) {
    render::FrameParams p;
    p.scale = scale;
    p.color = mode;
    expectAgree(both(set, cam, p), cam, "colour mode " + std::to_string(int(mode)));
  }
  render::FrameParams p;
  p.scale = scale;
  p.faMin = 0.3;
  p.slab = {2, 0.5, 2.5};
  expectAgree(both(set, cam, p), cam, "FA threshold and slab", 200);
}

// The eye inside a glyph and the eye plane cutting others: no finite
// rectangle, rays from inside see the far wall.
TEST_P(CastPaths, GlyphsAroundTheEyeMatchTheRasterPath) {
  const tensor::GlyphSet set = test::glyphsAroundTheEye();
  for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
    const auto cam = test::insideCamera(proj);
    expectAgree(both(set, cam, render::FrameParams{}), cam, "around the eye");
  }
}

// Deferred passes and context read the same G-buffer: AO and outlines on.
TEST_P(CastPaths, DepthCuesMatchTheRasterPath) {
  const tensor::GlyphSet set = grid(3, 5);
  const double scale = 0.5;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 7.0, render::Projection::Perspective), 160, 120);
  render::FrameParams p;
  p.scale = scale;
  p.ao.enabled = p.outline.enabled = true;
  const Pair s = both(set, cam, p);
  const Agreement g = agreement(s, cam);
  std::printf("[ cast path ] depth cues: %zu id mismatches, colour %.2g\n", g.idMismatch, g.color);
  EXPECT_LE(double(g.idMismatch), kIdMismatch * double(g.covered));
  // AO samples depth and normals around each pixel; rounding-level depth
  // differences could move a sample across a surface at grazing angles
  // (measured: none moved, colour within 1.5e-4).
  EXPECT_LT(g.color, kColor);
}

// Picking reads one pixel of the G-buffer (render/pixel_probe.h): the same
// glyph and depth on both paths.
TEST_P(CastPaths, PickingReadsThePathsGBuffer) {
  const tensor::GlyphSet set = grid(3, 9);
  const double scale = 0.5;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 7.0, render::Projection::Perspective), 120, 90);
  render::FrameParams p;
  p.scale = scale;
  ctx_->makeCurrent();
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  std::vector<render::PixelSample> picks[2];
  int k = 0;
  for (const std::string& path : {std::string("raster"), GetParam()}) {
    render::GlyphRenderer r(ctx_->api(), *lib_, nullptr, path);
    r.upload(set);
    r.render(cam, p, target);
    for (int j = 5; j < cam.height; j += 11)
      for (int i = 3; i < cam.width; i += 13) picks[k].push_back(render::readPixel(ctx_->api(), cam, target, i, j));
    ++k;
  }
  std::size_t hits = 0, same = 0;
  for (std::size_t i = 0; i < picks[0].size(); ++i) {
    if (picks[0][i].id == ref::kNoGlyph) continue;
    ++hits;
    if (picks[0][i].id != picks[1][i].id) continue;
    ++same;
    EXPECT_NEAR(picks[1][i].viewDepth, picks[0][i].viewDepth, kRelDepth * picks[0][i].viewDepth);
  }
  EXPECT_GT(hits, 10u);
  EXPECT_GE(double(same), double(hits) - 1.0);
}

// Superquadrics through the same march source: Kindlmann shapes (convex
// variant), Schultz-Kindlmann ones (mixed variant) and spheres cast as
// ellipsoids, at gamma 0 (definite glyphs then ellipsoids), 1, 3 and the
// extremes, both projections, the sign colour, and the general march alone.
TEST_P(CastPaths, SuperquadricsMatchTheRasterPath) {
  const tensor::GlyphSet set = grid(4, 13);
  const double scale = 0.45;
  for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
    const auto cam = test::cameraFor(set, scale, test::oblique(set, 9.0, proj), 200, 150);
    const std::string where = proj == render::Projection::Perspective ? "perspective" : "orthographic";
    for (const double gamma : {0.0, 1.0, 3.0, 1000.0}) {
      const Pair s = both(set, cam, test::superquadricParams(scale, gamma));
      expectAgree(s, cam, where + ", gamma " + std::to_string(gamma), 500, true);
      EXPECT_GT(s.cpuDrawn, 20u);
    }
  }
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 9.0, render::Projection::Perspective), 160, 120);
  render::FrameParams p = test::superquadricParams(scale, 3.0);
  p.color = render::ColorMode::Sign;
  expectAgree(both(set, cam, p), cam, "sign colour", 500, true);
  p.color = render::ColorMode::FA;
  p.marchVariants = false;
  expectAgree(both(set, cam, p), cam, "general march only", 500, true);
  p.march = {30, 1e-6};
  expectAgree(both(set, cam, p), cam, "tight march");
}

// Eigenvalue extremes (1e6:1, equal pairs, a negative definite) and glyphs
// around the eye, with a tight march; the gallery's glyphs of a zero
// eigenvalue on their own (tests/thin_glyphs.h): 1e-7 of their size thick,
// marched at GC coordinates near 1e6, where the paths' float maths (FMA and
// llvmpipe's exp2 and log2 against libm's) cover a few pixels differently.
// Measured: 16 of 2994 pixels (0.5%), all inside a disc {1, 0.5, 0} that the
// double reference covers, and the raster path with it.
TEST_P(CastPaths, SuperquadricExtremesMatchTheRasterPath) {
  const io::TensorField gallery = synth::extremesGallery(1.0, 1.0);
  const tensor::GlyphSet set = test::withoutFlatGlyphs(gallery), all = test::glyphsOf(gallery);
  for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
    const auto cam = test::cameraFor(all, 1.0, test::oblique(all, 40.0, proj), 320, 160);
    for (const double gamma : {0.0, 3.0, 20.0}) {
      render::FrameParams p = test::superquadricParams(1.0, gamma);
      p.march = {30, 1e-6};
      expectAgree(both(set, cam, p), cam, "extremes, gamma " + std::to_string(gamma));
      const Agreement g = agreement(both(all, cam, p), cam);
      std::printf("[ cast path ] flat glyphs too, gamma %g: %zu of %zu pixels differ\n", gamma, g.idMismatch, g.covered);
      EXPECT_LE(double(g.idMismatch), 0.01 * double(g.covered));
    }
    const auto inside = test::insideCamera(proj);
    expectAgree(both(test::glyphsAroundTheEye(), inside, test::superquadricParams(1.0, 3.0)), inside, "around the eye",
                500, true);
  }
}

// The stress field of the point load: every glyph of mixed sign.
TEST_P(CastPaths, StressSuperquadricsMatchTheRasterPath) {
  const io::TensorField f = synth::boussinesq(6, 0.3);
  const tensor::GlyphSet set = test::glyphsOf(f);
  // The default sizing: the load's neighbours overlap, as in a render.
  const tensor::ScaleParams sized;
  const double scale = tensor::resolveScale(sized, tensor::sampleMagnitudes(set, f.sampleSpacing)).scale;
  const double dist = 3.0 * glm::length(set.boundsMaxWC - set.boundsMinWC);
  const auto cam = test::cameraFor(set, scale, test::oblique(set, dist, render::Projection::Perspective), 200, 150);
  render::FrameParams p = test::superquadricParams(scale, 3.0);
  p.color = render::ColorMode::Sign;
  expectAgree(both(set, cam, p), cam, "point load", 500, true);
}

// The key light's shadow map comes from the raster path's casters on both
// paths, so that shadowed superquadrics light alike.
TEST_P(CastPaths, ShadowedSuperquadricsMatchTheRasterPath) {
  const tensor::GlyphSet set = grid(3, 17);
  const double scale = 0.5;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 7.0, render::Projection::Perspective), 160, 120);
  render::FrameParams p = test::superquadricParams(scale, 3.0);
  p.shadow.enabled = true;
  expectAgree(both(set, cam, p), cam, "shadows", 500, true);
}

// Teem's cylinders and boxes: the same closed forms (lib/prism.glsl) on
// both paths, in both projections, with sign colours (each face's point),
// the selection, a stress field's mixed signs, and the eye inside a glyph.
TEST_P(CastPaths, CylindersAndBoxesMatchTheRasterPath) {
  const tensor::GlyphSet set = grid(4, 7);
  const tensor::GlyphSet stress = test::glyphsOf(synth::boussinesq(6, 0.3));
  const double scale = 0.45;
  for (const auto kind : {render::GlyphKind::Cylinder, render::GlyphKind::Box}) {
    const std::string name(render::glyphKind(kind).name);
    for (const auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
      const auto cam = test::cameraFor(set, scale, test::oblique(set, 9.0, proj), 200, 150);
      render::FrameParams p;
      p.scale = scale;
      p.glyph = kind;
      const Pair s = both(set, cam, p);
      expectAgree(s, cam, name + (proj == render::Projection::Perspective ? ", perspective" : ", orthographic"));
      EXPECT_GT(s.cpuDrawn, 20u);
    }
    const auto cam = test::cameraFor(set, scale, test::oblique(set, 9.0, render::Projection::Perspective), 160, 120);
    render::FrameParams p;
    p.scale = scale;
    p.glyph = kind;
    p.color = render::ColorMode::Sign;
    expectAgree(both(set, cam, p), cam, name + ", sign colours");
    p.color = render::ColorMode::FA;
    p.faMin = 0.3;
    p.slab = {2, 0.5, 2.5};
    expectAgree(both(set, cam, p), cam, name + ", FA threshold and slab", 200);
    const double stressScale = 0.5 / stress.maxAbsEigenvalue;
    const auto stressCam = test::cameraFor(stress, stressScale, test::oblique(stress, 6.0, render::Projection::Perspective), 400, 300);
    render::FrameParams q;
    q.scale = stressScale;
    q.glyph = kind;
    expectAgree(both(stress, stressCam, q), stressCam, name + ", stress", 300);
    q.color = render::ColorMode::Sign;
    // Measured 2.2e-3 on the boxes (the cause not isolated: the sign weights
    // and GC point are set up in eigenvector order here, in GC order there);
    // held below one 8-bit step.
    expectAgree(both(stress, stressCam, q), stressCam, name + ", stress, sign colours", 300, false, 3.9e-3);
    const auto inside = test::insideCamera(render::Projection::Perspective);
    render::FrameParams e;
    e.glyph = kind;
    expectAgree(both(test::glyphsAroundTheEye(), inside, e), inside, name + ", around the eye");
  }
}

TEST_P(CastPaths, TessellatedFramesAreRefused) {
  const tensor::GlyphSet set = grid(2, 3);
  ctx_->makeCurrent();
  const auto cam = test::cameraFor(set, 0.5, test::oblique(set, 5.0, render::Projection::Perspective), 64, 48);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  render::GlyphRenderer r(ctx_->api(), *lib_, nullptr, GetParam());
  r.upload(set);
  render::FrameParams p;
  p.scale = 0.5;
  p.glyph = render::GlyphKind::Superquadric;
  p.tessellation = 8;
  try {
    r.render(cam, p, target);
    ADD_FAILURE() << "a tessellated frame was drawn";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("a tessellated frame needs the raster path"), std::string::npos) << e.what();
  }
}

// Blobs reach the G-buffer as castBlobs cast them: every pixel's id and
// depth (through an R32F texture, exact), and lit; with shadows the light's
// map is cast the same way, and the blobs shade themselves. The raster path
// refuses them.
TEST_F(CpuGlyphs, BlobsFillTheGBufferAsCastAndCastShadows) {
  const tensor::GlyphSet set = grid(3, 17);
  const double scale = 0.5;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 7.0, render::Projection::Perspective), 160, 120);
  render::FrameParams p;
  p.scale = scale;
  p.glyph = render::GlyphKind::Blob;
  p.blob.blobbiness = -1.0;
  ctx_->makeCurrent();
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  render::GlyphRenderer r(ctx_->api(), *lib_, nullptr, "cpu");
  r.upload(set);
  r.render(cam, p, target);
  const render::FrameImage plain = r.readback(cam, target);
  render::CpuCasts casts;
  std::vector<render::BlobCandidate> bumps;
  render::castBlobs(set.glyphs, cam, p, false, 2, casts, bumps);
  const render::FrameImage cast = test::asFrame(casts, set, cam);
  std::size_t covered = 0;
  for (std::size_t i = 0; i < cast.id.size(); ++i) {
    ASSERT_EQ(plain.id[i], cast.id[i]) << "pixel " << i;
    if (cast.id[i] == ref::kNoGlyph) continue;
    ++covered;
    EXPECT_NEAR(plain.depth[i], cast.depth[i], kRelDepth * cast.depth[i]);
  }
  EXPECT_GT(covered, 2000u);

  p.shadow.enabled = true;
  r.render(cam, p, target);
  ASSERT_NE(r.pass("shadow"), nullptr);
  const render::FrameImage shadowed = r.readback(cam, target);
  std::size_t darker = 0;
  for (std::size_t i = 0; i < cast.id.size(); ++i) {
    EXPECT_EQ(shadowed.id[i], cast.id[i]);
    darker += cast.id[i] != ref::kNoGlyph && shadowed.rgba[4 * i] < plain.rgba[4 * i] - 0.02f;
  }
  EXPECT_GT(darker, 100u) << "no blob shades another";

  render::GlyphRenderer raster(ctx_->api(), *lib_, nullptr, "raster");
  raster.upload(set);
  p.shadow.enabled = false;
  try {
    raster.render(cam, p, target);
    ADD_FAILURE() << "the raster path drew blobs";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("casts no blobs"), std::string::npos) << e.what();
  }
}

// One renderer whose frames change size (a viewer's window, the
// calibration of --pipeline auto): the casts' textures follow the frame.
TEST_P(CastPaths, FramesOfAnotherSizeMatchTheRasterPath) {
  const tensor::GlyphSet set = grid(4, 7);
  const double scale = 0.45;
  render::FrameParams p;
  p.scale = scale;
  ctx_->makeCurrent();
  render::GlyphRenderer cpu(ctx_->api(), *lib_, nullptr, GetParam());
  cpu.upload(set);
  for (const auto& [w, h] : {std::pair{120, 90}, std::pair{200, 150}, std::pair{96, 72}}) {
    const auto cam = test::cameraFor(set, scale, test::oblique(set, 9.0, render::Projection::Perspective), w, h);
    render::GBuffer target(ctx_->api(), w, h);
    cpu.render(cam, p, target);
    Pair s = both(set, cam, p);
    s.cpu = cpu.readback(cam, target);
    expectAgree(s, cam, std::to_string(w) + " x " + std::to_string(h), 200);
  }
}
