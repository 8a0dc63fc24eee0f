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

// Whether world box `b` covers world page (page.y, page.z) of level
// page.x, seen down the light, within a texel (virtual_cull.comp's test).
bool covers(const VirtualClipmap& clipmap, const glm::ivec4& page, const CasterBounds& b) {
  const LightView& view = clipmap.levels[static_cast<std::size_t>(page.x)].view;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner((c & 1) ? b.max.x : b.min.x, (c & 2) ? b.max.y : b.min.y,
                           (c & 4) ? b.max.z : b.min.z);
    const glm::vec2 p = glm::vec2(view.view * glm::vec4(corner, 1.0f));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const float texel = view.texel_world, size = texel * kVirtualPageTexels;
  const glm::vec2 page_lo = glm::vec2(page.y, page.z) * size - texel;
  const glm::vec2 page_hi = glm::vec2(page.y + 1, page.z + 1) * size + texel;
  return !(lo.x > page_hi.x || lo.y > page_hi.y || hi.x < page_lo.x || hi.y < page_lo.y);
}

TEST_F(GpuTest, VirtualPagesDrawEachCasterOnlyWhereItsBoundsCoverThem) {
  Scene scene = *builtin_scene("default");
  scene.lights.erase(scene.lights.begin());  // the sun alone
  Renderer renderer(scene);
  RenderSettings render;
  render.width = 240;
  render.height = 160;
  render.view = View::Shadow;
  ShadowSettings shadow;
  shadow.technique = Technique::Hard;
  shadow.shadow_maps = ShadowMapKind::Virtual;
  renderer.render(render, shadow);

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
      return covers(renderer.virtual_clipmap(), p, bounds);
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

}  // namespace
}  // namespace penumbra
