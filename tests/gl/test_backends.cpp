// Tier 3: the backends. OSMesa always; EGL where a display exists (Mesa's
// surfaceless platform here); GLFW where an X display exists (CI runs it under
// Xvfb with TG_REQUIRE_DISPLAY=1, so that a missing display fails instead of
// skipping). All in one process, each with its own entry points.
#include "render_fixture.h"

#include <cstdlib>
#include <string>

#include "data-synthetic/generators.h"

using namespace tg;

TEST(Backends, OSMesaGivesGL45Core) {
  auto ctx = gl::createOSMesaContext();
  EXPECT_STREQ(ctx->backendName(), "osmesa");
  GLint major = 0, minor = 0;
  ctx->api().GetIntegerv(GL_MAJOR_VERSION, &major);
  ctx->api().GetIntegerv(GL_MINOR_VERSION, &minor);
  EXPECT_GE(major * 10 + minor, 45) << ctx->describe();
}

namespace {

render::FrameImage drawRandomField(gl::Context& ctx, const render::Camera& cam) {
  const auto f = synth::randomField(64, 9);
  const auto set = tensor::buildGlyphs(f.positions, f.tensors, f.ids);
  const gl::ShaderLibrary lib;
  ctx.makeCurrent();
  render::GlyphRenderer r(ctx.api(), lib);
  render::GBuffer t(ctx.api(), cam.width, cam.height);
  r.upload(set);
  r.render(cam, {}, t);
  return r.readback(cam, t);
}

render::Camera obliqueCamera() {
  render::CameraDesc d;
  d.eyeWC = {12, -9, 10};
  d.lookAtWC = {1.5, 1.5, 1.5};
  d.upWC = {0, 0, 1};
  return render::makeCamera(d, 96, 72, glm::dvec3(-1), glm::dvec3(5));
}

// Two renders of the same scene agree on the glyph id of all but 1% of the
// covered pixels: different rasterisers may round pixel centres on glyph
// silhouettes differently, nothing more.
void expectSameIds(const render::FrameImage& a, const render::FrameImage& b, const std::string& what) {
  std::size_t covered = 0, differ = 0;
  for (std::size_t i = 0; i < a.id.size(); ++i) {
    covered += a.id[i] != ref::kNoGlyph;
    differ += a.id[i] != b.id[i];
  }
  EXPECT_GT(covered, 100u) << what;
  EXPECT_LE(differ, covered / 100) << what;
}

}  // namespace

TEST(Backends, AllThreeInOneProcessRenderTheSameIds) {
  std::unique_ptr<gl::Context> glfw;
  try {
    glfw = gl::createGlfwContext({.width = 96, .height = 72, .visible = false});
  } catch (const std::exception& e) {
    if (std::getenv("TG_REQUIRE_DISPLAY")) FAIL() << e.what();
    GTEST_SKIP() << "no X display: " << e.what();
  }
  auto osm = gl::createOSMesaContext();
  const auto cam = obliqueCamera();
  const auto a = drawRandomField(*osm, cam);
  const auto b = drawRandomField(*glfw, cam);
  expectSameIds(a, b, osm->describe() + " vs " + glfw->describe());
  std::unique_ptr<gl::Context> egl;
  try {
    egl = gl::createEglContext({});
  } catch (const std::exception&) {
    // No EGL display: OSMesaAndEglInOneProcessRenderTheSameIds reports it.
  }
  if (egl) {
    expectSameIds(a, drawRandomField(*egl, cam), "osmesa vs " + egl->describe());
    expectSameIds(b, drawRandomField(*glfw, cam), "glfw again after egl");
  }
}

TEST(Backends, OSMesaAndEglInOneProcessRenderTheSameIds) {
  std::unique_ptr<gl::Context> egl;
  try {
    egl = gl::createEglContext({});
  } catch (const std::exception& e) {
    GTEST_SKIP() << "no EGL display on this machine: " << e.what();
  }
  auto osm = gl::createOSMesaContext();
  const auto cam = obliqueCamera();
  expectSameIds(drawRandomField(*osm, cam), drawRandomField(*egl, cam), osm->describe() + " vs " + egl->describe());
}
