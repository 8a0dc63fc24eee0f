// Per-page caster culling of virtual shadow maps (VirtualShadowPass,
// shaders/shadow/virtual_cull.comp): each caster draw (one per shape and
// batch) is drawn only into the listed pages its bounds cover, as a CPU
// test of the same bounds against the same pages counts them.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/glm.hpp>

#include "gpu_fixture.hpp"
#include "penumbra/shadow/virtual_shadow_pass.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

// Whether world box `b` covers page (page.y, page.z) of level `level`
// within a texel (virtual_cull.comp's test): seen down the light for a
// clipmap level, through the spot's projection for a spot level (a box
// reaching behind the spot's eye covers every page).
bool covers(const VirtualLevel& level, const glm::ivec4& page, const CasterBounds& b) {
  const LightView& view = level.view;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int c = 0; c < 8; ++c) {
    const glm::vec4 corner((c & 1) ? b.max.x : b.min.x, (c & 2) ? b.max.y : b.min.y,
                           (c & 4) ? b.max.z : b.min.z, 1.0f);
    glm::vec2 p;
    if (view.perspective) {
      const glm::vec4 clip = view.projection * view.view * corner;
      if (clip.w <= 0.0f) return true;
      p = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * static_cast<float>(level.texels);
    } else {
      p = glm::vec2(view.view * corner) / view.texel_world;
    }
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec2 page_lo = glm::vec2(page.y, page.z) * float(kVirtualPageTexels) - 1.0f;
  const glm::vec2 page_hi = glm::vec2(page.y + 1, page.z + 1) * float(kVirtualPageTexels) + 1.0f;
  return !(lo.x > page_hi.x || lo.y > page_hi.y || hi.x < page_lo.x || hi.y < page_lo.y);
}

// Renders `scene`'s virtual maps once and checks every draw's page count
// against covers() over the pages listed (both lists).
void expect_culled(const Scene& scene) {
  Renderer renderer(scene);
  RenderSettings render;
  render.width = 240;
  render.height = 160;
  render.view = View::Shadow;
  ShadowSettings shadow;
  shadow.technique = Technique::Hard;
  shadow.shadow_maps = ShadowMapKind::Virtual;
  renderer.render(render, shadow);

  std::vector<VirtualLevel> levels;  // numbered across the lights, as the block's
  for (const VirtualLightMaps& maps : renderer.virtual_lights())
    levels.insert(levels.end(), maps.maps.levels.begin(), maps.maps.levels.end());
  const VirtualShadowPass& pass = renderer.virtual_shadows();
  const std::vector<glm::ivec4> pages = pass.read_render_list();
  const std::vector<int> drawn = pass.read_page_draws();
  ASSERT_GT(pages.size(), 4u);
  ASSERT_EQ(static_cast<int>(drawn.size()), pass.draw_count());
  ASSERT_GT(drawn.size(), 3u) << "one draw per shape";
  int smallest = static_cast<int>(pages.size());
  int total = 0;
  for (std::size_t d = 0; d < drawn.size(); ++d) {
    const CasterBounds bounds = pass.draw_bounds(d);
    const auto expected = std::count_if(pages.begin(), pages.end(), [&](const glm::ivec4& p) {
      return covers(levels.at(static_cast<std::size_t>(p.x)), p, bounds);
    });
    EXPECT_EQ(drawn[d], expected) << "draw " << d;
    smallest = std::min(smallest, drawn[d]);
    total += drawn[d];
  }
  // The objects' draws cover a few pages per level, the ground's most.
  EXPECT_LT(smallest * 4, static_cast<int>(pages.size()));
  EXPECT_EQ(renderer.virtual_page_stats().page_draws, total);
  EXPECT_LT(total, static_cast<int>(pages.size() * drawn.size()));
}

TEST_F(GpuTest, VirtualPagesDrawEachCasterOnlyWhereItsBoundsCoverThem) {
  Scene scene = *builtin_scene("default");
  ASSERT_EQ(scene.lights.front().type, LightType::Spot);
  scene.lights.erase(scene.lights.begin());  // the sun alone
  expect_culled(scene);
}

// A spot light's pages, drawn from the second (perspective) list, are
// culled through its projection.
TEST_F(GpuTest, VirtualSpotPagesDrawEachCasterOnlyWhereItsBoundsCoverThem) {
  Scene scene = *builtin_scene("default");
  scene.lights.resize(1);  // the spot alone
  ASSERT_EQ(scene.lights.front().type, LightType::Spot);
  expect_culled(scene);
}

}  // namespace
}  // namespace penumbra
