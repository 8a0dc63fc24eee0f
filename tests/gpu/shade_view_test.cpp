// Renderer::shade(): another view of the last frame from the maps, filters
// and G-buffer it left, identical to rendering that view anew.
#include <gtest/gtest.h>

#include <stdexcept>

#include "gpu_fixture.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

RenderSettings view(View v) {
  RenderSettings rs;
  rs.width = 96;
  rs.height = 64;
  rs.view = v;
  return rs;
}

TEST_F(GpuTest, ShadingAnotherViewMatchesRenderingIt) {
  Renderer renderer(*builtin_scene("default"));
  ShadowSettings pcss;
  pcss.technique = Technique::Pcss;
  pcss.map_size = 256;
  ShadowSettings msm = pcss;
  msm.technique = Technique::Msm;
  msm.blur = 4;
  ShadowSettings soft = msm;
  soft.filter = Filter::Sat;
  soft.soft = true;
  soft.blur = 1;
  for (const ShadowSettings& shadow : {pcss, msm, soft}) {
    const std::string name(enum_name<Technique>(kTechniqueNames, shadow.technique));
    for (View v : {View::Shadow, View::ShadowReference}) {
      renderer.render(view(v), shadow);
      const Image rendered = renderer.read_view();
      renderer.render(view(View::Final), shadow);
      const Image lit = renderer.read_view();
      renderer.shade(v);
      const Image shaded = renderer.read_view();
      EXPECT_EQ(shaded.rgba, rendered.rgba) << name << ", view " << static_cast<int>(v);
      EXPECT_NE(shaded.rgba, lit.rgba) << name;
      // And back: the lit view again, SSAO included.
      renderer.shade(View::Final);
      EXPECT_EQ(renderer.read_view().rgba, lit.rgba) << name;
    }
  }
}

// The lit image's pass leaves the chosen light's shadow view as well
// (LightingPass::shadow_output), which shade(View::Shadow) shows without a
// pass: for either light of the scene, and after another view's pass, which
// leaves no shadow view, from a pass of its own.
TEST_F(GpuTest, TheLitImageLeavesTheChosenLightsShadowView) {
  Renderer renderer(*builtin_scene("default"));
  ShadowSettings shadow;
  shadow.technique = Technique::Pcss;
  shadow.map_size = 256;
  for (int light : {0, 1}) {
    RenderSettings rs = view(View::Shadow);
    rs.light_index = light;
    renderer.render(rs, shadow);
    const Image rendered = renderer.read_view();
    rs.view = View::Final;
    renderer.render(rs, shadow);
    renderer.shade(View::Shadow);
    EXPECT_EQ(renderer.read_view().rgba, rendered.rgba) << "light " << light;
    renderer.shade(View::Normals);
    renderer.shade(View::Shadow);
    EXPECT_EQ(renderer.read_view().rgba, rendered.rgba) << "light " << light << ", after normals";
    // read_view() after read_texel_density() shows its values, as it says,
    // not the shadow view the lit image left.
    const Image density = renderer.read_texel_density();
    EXPECT_EQ(renderer.read_view().rgba, density.rgba) << "light " << light;
  }
}

TEST_F(GpuTest, ShadeRefusesWhatTheLastFrameDidNotMake) {
  Renderer renderer(*builtin_scene("default"));
  ShadowSettings shadow;
  shadow.map_size = 256;
  renderer.render(view(View::ShadowMap), shadow);
  EXPECT_THROW(renderer.shade(View::Shadow), std::logic_error) << "after a map view";
  renderer.render(view(View::Shadow), shadow);
  EXPECT_THROW(renderer.shade(View::Final), std::logic_error) << "SSAO was skipped";
  EXPECT_THROW(renderer.shade(View::ShadowMap), std::logic_error);
}

}  // namespace
}  // namespace penumbra
