#include <map>
#include <string>
#include <vector>

#include "gl/embedded_shaders.hpp"
#include "gpu_fixture.hpp"
#include "penumbra/filter/gaussian.hpp"
#include "penumbra/gl/program.hpp"
#include "penumbra/shared/bindings.h"

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

// Every shader entry point compiles and links, with the defines its pass
// compiles it with: compute shaders alone, the others as the pairs the
// passes use, and the lighting pass for every technique and filter.
TEST_F(GpuTest, EveryShaderCompiles) {
  shared_context();
  const std::map<std::string, std::vector<gl::Defines>> compute = {
      {"filter/resolve.comp",
       {{{"REPRESENTATION", std::to_string(TECHNIQUE_VSM)},
         {"MSM_QUANTIZED", "0"},
         {"IMAGE_FORMAT", "rg32f"}},
        {{"REPRESENTATION", std::to_string(TECHNIQUE_ESM)},
         {"MSM_QUANTIZED", "0"},
         {"IMAGE_FORMAT", "r32f"}},
        {{"REPRESENTATION", std::to_string(TECHNIQUE_MSM)},
         {"MSM_QUANTIZED", "0"},
         {"IMAGE_FORMAT", "rgba32f"}},
        {{"REPRESENTATION", std::to_string(TECHNIQUE_MSM)},
         {"MSM_QUANTIZED", "1"},
         {"IMAGE_FORMAT", "rgba32f"}},
        {{"REPRESENTATION", std::to_string(TECHNIQUE_MSM16)},
         {"MSM_QUANTIZED", "1"},
         {"IMAGE_FORMAT", "rgba16"}},
        {{"REPRESENTATION", std::to_string(TECHNIQUE_EVSM2)},
         {"MSM_QUANTIZED", "0"},
         {"IMAGE_FORMAT", "rg32f"}},
        {{"REPRESENTATION", std::to_string(TECHNIQUE_EVSM4)},
         {"MSM_QUANTIZED", "0"},
         {"IMAGE_FORMAT", "rgba32f"}}}},
      {"filter/fused_filter.comp",
       {{{"REPRESENTATION", std::to_string(TECHNIQUE_ESM)},
         {"MSM_QUANTIZED", "0"},
         {"IMAGE_FORMAT", "r32f"},
         {"RADIUS", "1"},
         {"TILE_Y", "32"},
         {"GAUSSIAN_WEIGHTS", "0.25, 0.5, 0.25"}},
        {{"REPRESENTATION", std::to_string(TECHNIQUE_EVSM4)},
         {"MSM_QUANTIZED", "0"},
         {"IMAGE_FORMAT", "rgba32f"},
         {"RADIUS", "2"},
         {"TILE_Y", "8"},
         {"GAUSSIAN_WEIGHTS", "0.1, 0.2, 0.4, 0.2, 0.1"}},
        // The direct staging's two passes (CPU rasterizers).
        {{"REPRESENTATION", std::to_string(TECHNIQUE_VSM)},
         {"MSM_QUANTIZED", "0"},
         {"IMAGE_FORMAT", "rg32f"},
         {"RADIUS", "1"},
         {"TILE_Y", "8"},
         {"GAUSSIAN_WEIGHTS", "0.25, 0.5, 0.25"},
         {"STAGE_IN_SHARED_MEMORY", "0"},
         {"PASS", "1"},
         {"ROWS_FORMAT", "rg32f"}},
        {{"REPRESENTATION", std::to_string(TECHNIQUE_MSM16)},
         {"MSM_QUANTIZED", "1"},
         {"IMAGE_FORMAT", "rgba16"},
         {"RADIUS", "1"},
         {"TILE_Y", "8"},
         {"GAUSSIAN_WEIGHTS", "0.25, 0.5, 0.25"},
         {"STAGE_IN_SHARED_MEMORY", "0"},
         {"PASS", "2"},
         {"ROWS_FORMAT", "rgba32f"}}}},
      {"filter/gaussian_blur.comp",
       {{{"AXIS", "0"},
         {"RADIUS", "1"},
         {"GAUSSIAN_WEIGHTS", gaussian_weight_list(1)},
         {"STAGE_IN_SHARED_MEMORY", "1"},
         {"IMAGE_FORMAT", "rgba16"}},
        {{"AXIS", "1"},
         {"RADIUS", "64"},
         {"GAUSSIAN_WEIGHTS", gaussian_weight_list(64)},
         {"STAGE_IN_SHARED_MEMORY", "0"},
         {"IMAGE_FORMAT", "rgba32f"}}}},
      {"filter/sat_rows.comp", {{{"IMAGE_FORMAT", "rgba32ui"}}, {{"IMAGE_FORMAT", "rg32ui"}}}},
      {"filter/sat_columns.comp", {{{"IMAGE_FORMAT", "rgba32ui"}}, {{"IMAGE_FORMAT", "r32ui"}}}},
      {"filter/sat_scan.comp",
       {{{"AXIS", "0"}, {"IMAGE_FORMAT", "rgba32ui"}}, {{"AXIS", "1"}, {"IMAGE_FORMAT", "r32ui"}}}},
      {"filter/sat_box.comp", {{}}},
      {"filter/copy.comp", {{{"IMAGE_FORMAT", "r32f"}}, {{"IMAGE_FORMAT", "rgba16"}}}},
      {"filter/downsample.comp",
       {{{"IMAGE_FORMAT", "r32f"}},
        {{"IMAGE_FORMAT", "rg32f"}},
        {{"IMAGE_FORMAT", "rgba32f"}},
        {{"IMAGE_FORMAT", "rgba16"}}}},
      {"filter/depth_hierarchy.comp", {{{"FROM_DEPTH", "1"}}, {{"FROM_DEPTH", "0"}}}},
      {"shadow/virtual_mark.comp", {{}}},
      {"shadow/virtual_allocate.comp", {{}}},
      {"shadow/virtual_dirty.comp", {{}}},
      {"shadow/virtual_bounds.comp", {{}}},
      {"shadow/virtual_cull.comp", {{}}},
      {"test/shadow_math.comp", {{}}},
      {"test/sat_rectangle.comp", {{}}},
      {"render/ssao.comp", {{}}},
      {"render/ssao_blur.comp", {{{"AXIS", "0"}}, {{"AXIS", "1"}}}},
      {"render/ssao_upsample.comp", {{}}},
      {"render/tile_views.comp",
       {{{"IMAGE_FORMAT", "r32f"}}, {{"IMAGE_FORMAT", "rg32f"}}, {{"IMAGE_FORMAT", "rgba32f"}}}},
      {"render/accumulate.comp", {{{"ACCUMULATE_STEP", "0"}}, {{"ACCUMULATE_STEP", "1"}}}},
  };
  for (const gl::EmbeddedFile& file : gl::embedded_shader_files()) {
    const std::string path(file.path);
    if (!path.ends_with(".comp")) continue;
    auto it = compute.find(path);
    ASSERT_NE(it, compute.end()) << path << ": add it to this test with its defines";
    for (const gl::Defines& defines : it->second) {
      EXPECT_NO_THROW(gl::Program::compute(path, defines)) << path;
    }
  }
  // The lookups' fetch-counting variant (LightingPass::count_fetches).
  for (int technique : {TECHNIQUE_PCSS, TECHNIQUE_BACKPROJECTION}) {
    EXPECT_NO_THROW(gl::Program::graphics(
        "common/fullscreen.vert", "render/lighting.frag",
        {{"SHADOW_TECHNIQUE", std::to_string(technique)}, {"SHADOW_COUNT_FETCHES", "1"}}))
        << technique;
  }
  // The programs of the other views, and of the options compiled in only
  // where they are on (LightingPass::program_for).
  for (int technique = TECHNIQUE_NONE; technique <= TECHNIQUE_EVSM4; ++technique) {
    for (const gl::Defines& defines :
         {gl::Defines{{"LIGHTING_VIEWS", std::to_string(LIGHTING_VIEWS_REFERENCE)}},
          gl::Defines{{"CONTACT_SHADOWS", "1"}}}) {
      gl::Defines with_technique = defines;
      with_technique.push_back({"SHADOW_TECHNIQUE", std::to_string(technique)});
      with_technique.push_back(
          {"SHADOW_FILTER",
           std::to_string(technique >= TECHNIQUE_VSM ? FILTER_GAUSSIAN : FILTER_NONE)});
      with_technique.push_back({"MSM_QUANTIZED", "0"});
      EXPECT_NO_THROW(
          gl::Program::graphics("common/fullscreen.vert", "render/lighting.frag", with_technique))
          << "lighting, technique " << technique << ", " << defines.front().first;
    }
  }
  for (const char* virtual_maps : {"0", "1"}) {
    EXPECT_NO_THROW(
        gl::Program::graphics("common/fullscreen.vert", "render/lighting.frag",
                              {{"LIGHTING_VIEWS", std::to_string(LIGHTING_VIEWS_INSPECT)},
                               {"SHADOW_TECHNIQUE", std::to_string(TECHNIQUE_PCF)},
                               {"VIRTUAL_SHADOWS", virtual_maps}}))
        << "lighting's inspecting views, virtual maps " << virtual_maps;
  }
  EXPECT_NO_THROW(gl::Program::graphics(
      "common/fullscreen.vert", "render/lighting.frag",
      {{"SHADOW_TECHNIQUE", std::to_string(TECHNIQUE_HARD)}, {"ACCUMULATE_SUBFRAMES", "1"}}));
  // The lookups through virtual maps (shaders/shadow/virtual_shadow.glsl).
  for (int technique : {TECHNIQUE_HARD, TECHNIQUE_PCF, TECHNIQUE_PCSS, TECHNIQUE_BACKPROJECTION}) {
    EXPECT_NO_THROW(gl::Program::graphics(
        "common/fullscreen.vert", "render/lighting.frag",
        {{"SHADOW_TECHNIQUE", std::to_string(technique)}, {"VIRTUAL_SHADOWS", "1"}}))
        << "virtual lighting, technique " << technique;
  }
  const char* pairs[][2] = {{"shadow/shadow_depth.vert", "shadow/shadow_depth.frag"},
                            {"scene/gbuffer.vert", "scene/gbuffer.frag"}};
  for (auto& pair : pairs) {
    EXPECT_NO_THROW(gl::Program::graphics(pair[0], pair[1])) << pair[0] << " + " << pair[1];
  }
  for (int technique = TECHNIQUE_NONE; technique <= TECHNIQUE_EVSM4; ++technique) {
    for (int filter = FILTER_NONE; filter <= FILTER_SAT; ++filter) {
      for (const char* quantized : {"0", "1"}) {
        for (const char* soft : {"0", "1"}) {
          EXPECT_NO_THROW(gl::Program::graphics("common/fullscreen.vert", "render/lighting.frag",
                                                {{"SHADOW_TECHNIQUE", std::to_string(technique)},
                                                 {"SHADOW_FILTER", std::to_string(filter)},
                                                 {"MSM_QUANTIZED", quantized},
                                                 {"SOFT_SHADOWS", soft}}))
              << "lighting, technique " << technique << ", filter " << filter << ", soft " << soft;
        }
      }
    }
  }
}

}  // namespace
}  // namespace penumbra
