// The renderer keeps each light's fitted views between frames: they must
// follow every change that moves them (a light, the camera for cascades,
// the map size) and match what a new renderer fits.
#include <gtest/gtest.h>

#include "gpu_fixture.hpp"
#include "penumbra/shadow/shadow_views.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

RenderSettings small_view() {
  RenderSettings rs;
  rs.width = 64;
  rs.height = 48;
  return rs;
}

// Light i's views as a renderer made for `scene` fits them.
LightShadowViews fresh_views(const Scene& scene, const ShadowSettings& shadow, int light) {
  Renderer renderer(scene);
  renderer.render(small_view(), shadow);
  return renderer.shadow_views(light);
}

void expect_same_views(const LightShadowViews& a, const LightShadowViews& b) {
  ASSERT_EQ(a.views.size(), b.views.size());
  for (std::size_t v = 0; v < a.views.size(); ++v) {
    EXPECT_EQ(a.views[v].view_projection, b.views[v].view_projection) << "view " << v;
    EXPECT_EQ(a.views[v].z0, b.views[v].z0) << "view " << v;
    EXPECT_EQ(a.views[v].z1, b.views[v].z1) << "view " << v;
  }
  EXPECT_EQ(a.cascade_end, b.cascade_end);
}

TEST(ShadowViewInputs, OnlyCascadesFollowTheCamera) {
  ShadowSettings shadow;
  CameraFrustum near_camera, far_camera;
  far_camera.position = {5.0f, 1.0f, 3.0f};
  for (LightType type : {LightType::Spot, LightType::Point, LightType::Directional}) {
    Light light;
    light.type = type;
    const bool follows = shadow_view_inputs(light, near_camera, shadow) !=
                         shadow_view_inputs(light, far_camera, shadow);
    EXPECT_EQ(follows, type == LightType::Directional)
        << enum_name<LightType>(kLightTypeNames, type);
  }
}

TEST_F(GpuTest, MovedLightsAndCameraAreRefitted) {
  Scene scene = *builtin_scene("default");
  Light point;
  point.type = LightType::Point;
  point.position = {-2.0f, 4.0f, 1.0f};
  point.intensity = 20.0f;
  scene.lights.push_back(point);  // spot, sun (cascades), point
  ShadowSettings shadow;
  shadow.map_size = 256;

  Renderer renderer(scene);
  renderer.render(small_view(), shadow);
  const LightShadowViews spot_before = renderer.shadow_views(0);
  const LightShadowViews sun_before = renderer.shadow_views(1);

  // Move the spot and the point light, and the camera the cascades follow.
  Scene moved = scene;
  moved.lights[0].position += glm::vec3(1.0f, 0.5f, -0.5f);
  moved.lights[2].position += glm::vec3(0.5f, 0.0f, 0.5f);
  moved.camera.position += glm::vec3(-2.0f, 1.0f, 0.0f);
  renderer.set_lights(moved.lights);
  renderer.set_camera(moved.camera);
  renderer.render(small_view(), shadow);
  EXPECT_NE(renderer.shadow_views(0).views[0].view_projection,
            spot_before.views[0].view_projection);
  EXPECT_NE(renderer.shadow_views(1).views[0].view_projection, sun_before.views[0].view_projection);
  for (int light = 0; light < 3; ++light) {
    SCOPED_TRACE(light);
    expect_same_views(renderer.shadow_views(light), fresh_views(moved, shadow, light));
  }

  // A new map size changes every view's texel snapping and guard band.
  shadow.map_size = 128;
  renderer.render(small_view(), shadow);
  for (int light = 0; light < 3; ++light) {
    SCOPED_TRACE(light);
    expect_same_views(renderer.shadow_views(light), fresh_views(moved, shadow, light));
  }
}

}  // namespace
}  // namespace penumbra
