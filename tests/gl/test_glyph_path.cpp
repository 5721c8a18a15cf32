// Tier 3: the glyph-path seam (render/glyph_path.h). A path of the test's
// own fills the G-buffer from the CPU with the reference ray caster's
// ellipsoid (src/ref), its depth through the float channel and the resolve
// pass (render/depth_resolve.h); the renderer's deferred passes shade it, and
// the picture must match the raster path's.
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "render/depth_resolve.h"
#include "render/shadow_pass.h"
#include "render_fixture.h"

using namespace tg;
using test::GlFixture;

namespace {

class UploadedReference final : public render::GlyphPath {
 public:
  UploadedReference(const gl::Api& gl, const gl::ShaderLibrary& lib) : gl_(gl), lib_(lib) {}
  std::string_view name() const override { return "uploaded-reference"; }
  void upload(const tensor::GlyphSet& set) override { set_ = set; }
  void setParams(const render::FrameParams&, const render::FrameParams*) override {}
  void drawView(const render::Camera& cam, const render::FrameParams& p, const render::GBuffer& target) override {
    const ref::RefImage img = ref::renderEllipsoids(cam, set_.glyphs, {p.scale, p.faMin, p.sizing});
    std::unordered_map<std::uint32_t, const tensor::GlyphRecord*> byId;
    for (const auto& g : set_.glyphs) byId[g.id] = &g;
    const std::size_t n = std::size_t(cam.width) * std::size_t(cam.height);
    std::vector<float> albedo(4 * n, 0.0f), normal(4 * n, 0.0f), depth(n, 0.0f);
    std::vector<std::uint32_t> id(n);
    for (int j = 0; j < cam.height; ++j)
      for (int i = 0; i < cam.width; ++i) {
        const std::size_t src = std::size_t(j) * cam.width + i;             // rows top first
        const std::size_t dst = std::size_t(cam.height - 1 - j) * cam.width + i;  // GL: bottom first
        id[dst] = img.id[src];
        if (img.id[src] == ref::kNoGlyph) continue;
        const tensor::GlyphRecord& g = *byId.at(img.id[src]);
        glm::dvec3 axes[3];
        tensor::frameAxes(g, axes);
        // Directionally encoded colour, as lib/color.glsl's decColor.
        const double fa = std::clamp(double(g.fa), 0.0, 1.0);
        for (int k = 0; k < 3; ++k) {
          albedo[4 * dst + k] = float((1.0 - fa) + fa * std::abs(axes[0][k]));
          normal[4 * dst + k] = float(img.normalWC[src][k]);
        }
        albedo[4 * dst + 3] = 1.0f;
        depth[dst] = float(cam.windowDepthFromViewDepth(img.depth[src]));
      }
    target.beginGeometry();
    const int w = cam.width, h = cam.height;
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl_.TextureSubImage2D(target.texture(render::Attachment::Albedo), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, albedo.data());
    gl_.TextureSubImage2D(target.texture(render::Attachment::NormalWC), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, normal.data());
    gl_.TextureSubImage2D(target.texture(render::Attachment::Id), 0, 0, 0, w, h, GL_RED_INTEGER, GL_UNSIGNED_INT, id.data());
    if (!resolve_ || resolve_->gpuBytes() != 4 * n) resolve_ = std::make_unique<render::DepthResolve>(gl_, lib_, w, h);
    resolve_->upload(depth);
    resolve_->resolve(target);
    ++frames;
  }
  std::pair<glm::dvec3, glm::dvec3> castersBoxWC(const render::FrameParams& p) const override {
    const tensor::BoxWC box = tensor::glyphBoxWC(set_, p.scale);
    return {box.lo, box.hi};
  }
  void drawShadowCasters(const render::Camera& light, const render::FrameParams&, render::ShadowPass& shadow) override {
    shadow.beginMap(light.width);
  }
  std::size_t gpuBytes() const override { return resolve_ ? resolve_->gpuBytes() : 0; }
  std::uint64_t drawnGlyphs() const override { return set_.glyphs.size(); }
  int frames = 0;

 private:
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  tensor::GlyphSet set_;
  std::unique_ptr<render::DepthResolve> resolve_;
};

struct Shot {
  render::FrameImage img;
  int pathFrames = 0;
};

// One reference glyph, tilted, filling part of the frame.
tensor::GlyphSet oneGlyph() {
  const float pos[3] = {0, 0, 0};
  const float ten[6] = {1.0f, 0.25f, 0.1f, 0.5f, -0.1f, 0.3f};
  return tensor::buildGlyphs(std::span(pos, 3), std::span(ten, 6), {});
}

}  // namespace

TEST(GlyphPath, PathsAreSelectedByName) {
  EXPECT_EQ(render::glyphPathNames(), "raster, cpu, compute");
  auto ctx = gl::createOSMesaContext();
  const gl::ShaderLibrary lib;
  EXPECT_EQ(render::makeGlyphPath("raster", ctx->api(), lib)->name(), "raster");
  EXPECT_EQ(render::makeGlyphPath("cpu", ctx->api(), lib)->name(), "cpu");
  EXPECT_EQ(render::makeGlyphPath("compute", ctx->api(), lib)->name(), "compute");
  try {
    render::makeGlyphPath("tiles", ctx->api(), lib);
    ADD_FAILURE() << "an unknown path was made";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"tiles\"; choose raster, cpu, compute"), std::string::npos) << e.what();
  }
}

// The deferred passes shade a G-buffer made on the CPU as they shade the
// raster path's, with and without the depth cues (AO reads depth and
// normals, outlines depth, normals and ids). Tolerances: silhouette pixels
// may take either id, on 1% of the covered pixels (test_render.cpp's bound;
// measured: none); elsewhere the lit colour may differ by float rounding of
// the normal (< 0.03 deg after RGBA16F storage) and the depth: measured
// 1.8e-4, bound 1e-3, below one 8-bit albedo step (3.9e-3), a wrong normal
// or depth (the head light's half vector), or a channel left unwritten
// (an unresolved depth leaves every pixel the background).
TEST_F(GlFixture, ACpuMadeGBufferIsShadedAsTheRasterPath) {
  const tensor::GlyphSet set = oneGlyph();
  const double scale = 1.0;
  const auto cam = test::cameraFor(set, scale, test::oblique(set, 5.0, render::Projection::Perspective), 128, 96);
  for (const bool effects : {false, true}) {
    SCOPED_TRACE(effects ? "with AO and outlines" : "plain lighting");
    render::FrameParams p;
    p.scale = scale;
    p.ao.enabled = p.outline.enabled = effects;
    ctx_->makeCurrent();
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    render::GlyphRenderer raster(ctx_->api(), *lib_);
    raster.upload(set);
    raster.render(cam, p, target);
    const render::FrameImage a = raster.readback(cam, target);
    auto path = std::make_unique<UploadedReference>(ctx_->api(), *lib_);
    UploadedReference& uploaded = *path;
    render::GlyphRenderer cpu(ctx_->api(), *lib_, nullptr, std::move(path));
    cpu.upload(set);
    cpu.render(cam, p, target);
    const render::FrameImage b = cpu.readback(cam, target);
    EXPECT_EQ(uploaded.frames, 1);
    std::size_t covered = 0, edge = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < a.id.size(); ++i) {
      const bool inA = a.id[i] != ref::kNoGlyph, inB = b.id[i] != ref::kNoGlyph;
      covered += inA ? 1 : 0;
      if (a.id[i] != b.id[i]) {
        ++edge;
        continue;
      }
      for (int k = 0; k < 3; ++k) worst = std::max(worst, double(std::abs(a.rgba[4 * i + k] - b.rgba[4 * i + k])));
      if (!(inA && inB)) continue;
      EXPECT_LT(std::abs(a.depth[i] - b.depth[i]), 1e-4 * a.depth[i]) << "pixel " << i;
    }
    EXPECT_GT(covered, 500u);
    EXPECT_LE(double(edge), 0.01 * double(covered));
    EXPECT_LT(worst, 1e-3);
  }
}
