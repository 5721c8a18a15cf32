// Tier 2: shader composition fails loudly and maps errors back to files.
#include <gtest/gtest.h>

#include "gl/shader_library.h"

using tg::gl::ShaderLibrary;

namespace {
ShaderLibrary lib() {
  return ShaderLibrary({{"main.frag", "#version 450 core\n#include \"lib/a.glsl\"\nvoid main() {}\n"},
                        {"lib/a.glsl", "#include \"lib/b.glsl\"\nfloat a() { return b(); }\n"},
                        {"lib/b.glsl", "float b() { return 1.0; }\n"},
                        {"cycle.frag", "#version 450 core\n#include \"lib/c1.glsl\"\n"},
                        {"lib/c1.glsl", "#include \"lib/c2.glsl\"\n"},
                        {"lib/c2.glsl", "#include \"lib/c1.glsl\"\n"},
                        {"missing.frag", "#version 450 core\n#include \"lib/nope.glsl\"\n"},
                        {"tag.frag", "#version 450 core\n#pragma tg special\n"},
                        {"noversion.frag", "void main() {}\n"},
                        {"twice.frag", "#version 450 core\n#include \"lib/b.glsl\"\n#include \"lib/b.glsl\"\n"}});
}
}  // namespace

TEST(ShaderLibrary, ExpandsIncludesOnceWithLineDirectives) {
  const auto c = lib().compose("main.frag");
  ASSERT_EQ(c.files.size(), 3u);
  EXPECT_EQ(c.files[1], "lib/a.glsl");
  EXPECT_NE(c.text.find("float b()"), std::string::npos);
  EXPECT_NE(c.text.find("#line 1 2"), std::string::npos);
  EXPECT_NE(c.text.find("#line 3 0"), std::string::npos);  // back in main.frag after the include
  const auto t = lib().compose("twice.frag");
  EXPECT_EQ(t.text.find("float b()"), t.text.rfind("float b()"));
}

TEST(ShaderLibrary, ErrorsAreLoud) {
  EXPECT_THROW(lib().compose("nope.frag"), std::runtime_error);
  EXPECT_THROW(lib().compose("missing.frag"), std::runtime_error);
  EXPECT_THROW(lib().compose("cycle.frag"), std::runtime_error);
  EXPECT_THROW(lib().compose("tag.frag"), std::runtime_error);
  EXPECT_THROW(lib().compose("noversion.frag"), std::runtime_error);
  try {
    lib().compose("missing.frag");
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.frag:2"), std::string::npos) << e.what();
  }
}

TEST(ShaderLibrary, MapsCompilerLogsToFiles) {
  const auto c = lib().compose("main.frag");
  EXPECT_EQ(ShaderLibrary::mapLog("1:2(5): error: x", c), "lib/a.glsl:2: error: x");  // Mesa
  EXPECT_EQ(ShaderLibrary::mapLog("2(7) : error C0000: y", c), "lib/b.glsl:7 : error C0000: y");  // NVIDIA
}

TEST(ShaderLibrary, EmbeddedShadersAllCompose) {
  const ShaderLibrary real;
  for (const auto& f : tg::gl::embeddedShaderFiles())
    if (!f.path.starts_with("lib/")) {
      EXPECT_NO_THROW(real.compose(f.path)) << f.path;
    }
}
