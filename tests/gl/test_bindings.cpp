// The binding table shared by the C++ and the GLSL (shaders/lib/bindings.h):
// no shader names a binding by number, and what the compiled programs hold
// is what the C++ binds.
#include <regex>
#include <string>

#include "render_fixture.h"
#include "shaders/lib/bindings.h"

using namespace tg;
using test::GlFixture;

TEST(Bindings, NoShaderNamesABindingByNumber) {
  const std::regex numbered(R"(binding\s*=\s*[0-9])");
  for (const auto& f : gl::embeddedShaderFiles()) {
    // The ParaView host's compositing shader binds what the plugin's own code binds.
    if (f.path == "host_composite.frag") continue;
    EXPECT_FALSE(std::regex_search(std::string(f.text), numbered)) << f.path;
  }
}

TEST_F(GlFixture, ProgramsHoldTheTablesUnits) {
  ctx_->makeCurrent();
  const gl::Api& api = ctx_->api();
  const gl::Program lighting(api, *lib_, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "lighting.frag"}},
                             {"TG_AO", "TG_SHADOWS"});
  const gl::Program ao(api, *lib_, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "ao_blur.frag"}});
  auto unit = [&](const gl::Program& p, const char* name) {
    const GLint loc = api.GetUniformLocation(p.id(), name);
    EXPECT_GE(loc, 0) << name;
    GLint v = -1;
    api.GetUniformiv(p.id(), loc, &v);
    return v;
  };
  EXPECT_EQ(unit(lighting, "uAlbedo"), TG_UNIT_ALBEDO);
  EXPECT_EQ(unit(lighting, "uNormalWC"), TG_UNIT_NORMAL);
  EXPECT_EQ(unit(lighting, "uId"), TG_UNIT_ID);
  EXPECT_EQ(unit(lighting, "uAo"), TG_UNIT_AO);
  EXPECT_EQ(unit(lighting, "uSceneDepth"), TG_UNIT_SHADOW_SCENE_DEPTH);
  EXPECT_EQ(unit(lighting, "uShadowMap"), TG_UNIT_SHADOW_MAP);
  EXPECT_EQ(unit(ao, "uDepth"), TG_UNIT_EFFECT_DEPTH);
  EXPECT_EQ(unit(ao, "uRawAo"), TG_UNIT_AO_RAW);
}
