#include <string>

#include "gl/embedded_shaders.hpp"
#include "gl/program.hpp"
#include "gpu_fixture.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;
using testing::shared_context;

TEST_F(GpuTest, ContextIsOpenGl45Core) {
  gl::Context& ctx = shared_context();
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45) << ctx.version();
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_FALSE(ctx.renderer().empty());
  std::printf("OpenGL: %s, %s via %s\n", ctx.renderer().c_str(), ctx.version().c_str(),
              ctx.platform().c_str());
}

TEST_F(GpuTest, DebugOutputCountsErrors) {
  gl::Context& ctx = shared_context();
  const int before = ctx.error_count();
  glBindTextureUnit(0, 0xdeadbeef);  // not a texture name: GL_INVALID_OPERATION
  EXPECT_EQ(ctx.error_count(), before + 1);
  // Undo the count so the fixture's own check passes.
  SetUp();
}

// Every shader entry point compiles and links (compute shaders alone, the
// others as the vertex/fragment pairs the passes use).
TEST_F(GpuTest, EveryShaderCompiles) {
  shared_context();
  int compiled = 0;
  for (const gl::EmbeddedFile& file : gl::embedded_shader_files()) {
    const std::string path(file.path);
    if (path.ends_with(".comp")) {
      EXPECT_NO_THROW(gl::Program::compute(path)) << path;
      ++compiled;
    }
  }
  const char* pairs[][2] = {{"shadow/shadow_depth.vert", "shadow/shadow_depth.frag"},
                            {"scene/gbuffer.vert", "scene/gbuffer.frag"}};
  for (auto& pair : pairs) {
    EXPECT_NO_THROW(gl::Program::graphics(pair[0], pair[1])) << pair[0] << " + " << pair[1];
    ++compiled;
  }
  for (int technique : {0, 1}) {
    EXPECT_NO_THROW(gl::Program::graphics("common/fullscreen.vert", "render/lighting.frag",
                                          {{"SHADOW_TECHNIQUE", std::to_string(technique)}}))
        << "lighting, technique " << technique;
    ++compiled;
  }
  EXPECT_GE(compiled, 4);
}

}  // namespace
}  // namespace penumbra
