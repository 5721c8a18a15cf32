// Tier 3: the backends. OSMesa always; EGL where a display exists (Mesa's
// surfaceless platform here); both in one process with their own entry points.
#include "render_fixture.h"

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

TEST(Backends, OSMesaAndEglInOneProcessRenderTheSameIds) {
  std::unique_ptr<gl::Context> egl;
  try {
    egl = gl::createEglContext({});
  } catch (const std::exception& e) {
    GTEST_SKIP() << "no EGL display on this machine: " << e.what();
  }
  auto osm = gl::createOSMesaContext();
  const auto f = synth::randomField(64, 9);
  const auto set = tensor::buildGlyphs(f.positions, f.tensors, f.ids);
  render::CameraDesc d;
  d.eyeWC = {12, -9, 10};
  d.lookAtWC = {1.5, 1.5, 1.5};
  d.upWC = {0, 0, 1};
  const auto cam = render::makeCamera(d, 96, 72, glm::dvec3(-1), glm::dvec3(5));
  const gl::ShaderLibrary lib;
  auto drawWith = [&](gl::Context& ctx) {
    ctx.makeCurrent();
    render::GlyphRenderer r(ctx.api(), lib);
    render::GBuffer t(ctx.api(), cam.width, cam.height);
    r.upload(set);
    r.render(cam, {}, t);
    return r.readback(cam, t);
  };
  const auto a = drawWith(*osm);
  const auto b = drawWith(*egl);
  std::size_t covered = 0;
  for (std::size_t i = 0; i < a.id.size(); ++i) covered += a.id[i] != ref::kNoGlyph;
  EXPECT_GT(covered, 100u);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.id.size(); ++i) differ += a.id[i] != b.id[i];
  EXPECT_LE(differ, covered / 100) << osm->describe() << " vs " << egl->describe();
}
