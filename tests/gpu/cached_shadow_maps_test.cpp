// The renderer's cached shadow maps (Renderer::forget_shadow_maps,
// move_shape): a static frame draws no shadow view, a moved shape draws
// the views that see it, and every image equals the one drawn without the
// cache.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "gpu_fixture.hpp"
#include "penumbra/shadow/view_cache.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

RenderSettings small_view(View view = View::Final) {
  RenderSettings rs;
  rs.width = 96;
  rs.height = 64;
  rs.view = view;
  return rs;
}

ShadowSettings small_maps(Technique technique) {
  ShadowSettings s;
  s.technique = technique;
  s.map_size = 128;
  return s;
}

// The image of the same frame with every shadow view drawn anew.
Image uncached(Renderer& renderer, const RenderSettings& render, const ShadowSettings& shadow) {
  renderer.forget_shadow_maps();
  renderer.render(render, shadow);
  return renderer.read_view();
}

TEST_F(GpuTest, StaticFrameDrawsNoShadowView) {
  Renderer renderer(*builtin_scene("default"));
  renderer.render(small_view(), small_maps(Technique::Pcf));
  const int views = renderer.shadow_views_drawn();
  EXPECT_EQ(views, 4) << "a spot light's view and the sky's three cascades";
  // The same frame again; then another technique, whose depth maps are the
  // same (its filters run on them, no view is drawn).
  for (Technique t : {Technique::Pcf, Technique::Msm}) {
    const ShadowSettings shadow = small_maps(t);
    renderer.render(small_view(), shadow);
    EXPECT_EQ(renderer.shadow_views_drawn(), 0);
    const Image cached = renderer.read_view();
    EXPECT_EQ(cached.rgba, uncached(renderer, small_view(), shadow).rgba);
    EXPECT_EQ(renderer.shadow_views_drawn(), views);
    renderer.render(small_view(), shadow);
    EXPECT_EQ(renderer.shadow_views_drawn(), 0);
  }
}

// Each shape of the default scene moved in turn: the views drawn are
// those whose fit changed or that see the shape before or after; a view
// that sees neither box and kept its fit is not drawn; the image equals
// the uncached one. (The default scene's own views all see every object:
// a second spot light over a corner of the ground sees none.)
TEST_F(GpuTest, MovedShapeDrawsTheViewsThatSeeIt) {
  Scene scene = *builtin_scene("default");
  Light corner = scene.lights.front();
  corner.position = {9.0f, 8.0f, -9.0f};
  corner.direction = {0.0f, -1.0f, 0.0f};
  corner.cone_degrees = 20.0f;
  corner.inner_cone_degrees = 15.0f;
  scene.lights.push_back(corner);
  Renderer renderer(scene);
  const ShadowSettings shadow = small_maps(Technique::Vsm);
  const RenderSettings render = small_view();
  renderer.render(render, shadow);
  const int light_count = static_cast<int>(renderer.scene().lights.size());
  auto views_of = [&] {
    std::vector<LightView> all;
    for (int l = 0; l < light_count; ++l) {
      const LightShadowViews& v = renderer.shadow_views(l);
      all.insert(all.end(), v.views.begin(), v.views.end());
    }
    return all;
  };
  int fewer = 0;  // moves that drew fewer than every view
  for (std::size_t shape = 1; shape < renderer.scene().shapes.size(); ++shape) {
    const std::vector<LightView> before_views = views_of();
    const Bounds before = renderer.shape_bounds(shape);
    renderer.move_shape(shape, {0.25f, 0.0f, 0.0f});
    const Bounds after = renderer.shape_bounds(shape);
    EXPECT_EQ(after.min.x, before.min.x + 0.25f);
    renderer.render(render, shadow);
    const int drawn = renderer.shadow_views_drawn();
    const std::vector<LightView> after_views = views_of();
    int expected = 0;
    for (std::size_t v = 0; v < after_views.size(); ++v) {
      const bool refitted = after_views[v].view_projection != before_views[v].view_projection ||
                            after_views[v].z0 != before_views[v].z0 ||
                            after_views[v].z1 != before_views[v].z1;
      const glm::mat4& vp = after_views[v].view_projection;
      const bool sees = box_may_be_seen(vp, {before.min, before.max}) ||
                        box_may_be_seen(vp, {after.min, after.max});
      expected += refitted || sees;
    }
    EXPECT_EQ(drawn, expected) << "shape " << shape;
    fewer += drawn < static_cast<int>(after_views.size());
    const Image cached = renderer.read_view();
    EXPECT_EQ(cached.rgba, uncached(renderer, render, shadow).rgba) << "shape " << shape;
    renderer.render(render, shadow);
    EXPECT_EQ(renderer.shadow_views_drawn(), 0);
  }
  EXPECT_GT(fewer, 0) << "every move drew every view: the test shows no caching";
}

// Renderer::release_filtered_maps: the next frame makes the freed arrays
// again and equals the frame before (a fused filter, a summed-area table, a
// hierarchy, and a map view's resolve and tiled image); shade() waits for
// that frame.
TEST_F(GpuTest, ReleasedFilteredMapsAreMadeAgain) {
  Renderer renderer(*builtin_scene("default"));
  ShadowSettings soft = small_maps(Technique::Msm);
  soft.filter = Filter::Sat;
  soft.soft = true;
  soft.blur = 1;
  const std::pair<RenderSettings, ShadowSettings> frames[] = {
      {small_view(), small_maps(Technique::Msm)},
      {small_view(), soft},
      {small_view(), small_maps(Technique::Backprojection)},
      {small_view(View::Moments), small_maps(Technique::Esm)},
      {small_view(View::MomentsFiltered), small_maps(Technique::Vsm)}};
  for (const auto& [render, shadow] : frames) {
    renderer.render(render, shadow);
    const Image before = renderer.read_view();
    renderer.release_filtered_maps();
    EXPECT_THROW(renderer.shade(View::Shadow), std::logic_error);
    renderer.render(render, shadow);
    EXPECT_EQ(renderer.shadow_views_drawn(), 0) << "the depth maps are kept";
    EXPECT_EQ(before.rgba, renderer.read_view().rgba)
        << enum_name<Technique>(kTechniqueNames, shadow.technique);
  }
}

}  // namespace
}  // namespace penumbra
