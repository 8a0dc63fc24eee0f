#include "penumbra/gl/shader_source.hpp"

#include <gtest/gtest.h>

#include "penumbra/error.hpp"

namespace penumbra::gl {
namespace {

TEST(ShaderSource, ExpandsIncludesOnceWithLineDirectives) {
  ShaderSource s = assemble_shader("render/lighting.frag", {{"SHADOW_TECHNIQUE", "1"}});
  EXPECT_EQ(s.text.rfind("#version 450 core\n", 0), 0u);
  EXPECT_NE(s.text.find("#define SHADOW_TECHNIQUE 1"), std::string::npos);
  EXPECT_EQ(s.text.find("#include \""), std::string::npos);
  // bindings.h is reached through two includes but pasted once.
  int count = 0;
  for (const std::string& f : s.files) count += f == "shared/bindings.h";
  EXPECT_EQ(count, 1);
  EXPECT_EQ(s.files.front(), "render/lighting.frag");
}

TEST(ShaderSource, MissingFileIsAnError) {
  EXPECT_THROW(assemble_shader("no/such.frag", {}), RuntimeError);
}

TEST(ShaderSource, CompileLogsNameFileAndLine) {
  std::vector<std::string> files = {"render/lighting.frag", "shadow/hard.glsl"};
  EXPECT_EQ(map_compile_log("1:12(5): error: `x' undeclared\n", files),
            "shadow/hard.glsl:12: error: `x' undeclared\n");
  EXPECT_EQ(map_compile_log("0(7) : error C1008: undefined variable \"y\"\n", files),
            "render/lighting.frag:7: error C1008: undefined variable \"y\"\n");
}

}  // namespace
}  // namespace penumbra::gl
