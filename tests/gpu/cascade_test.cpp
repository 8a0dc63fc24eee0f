// Cascaded directional shadows on the GPU: every visible pixel reads a
// cascade that covers it, the splits increase to the camera's far plane,
// and a camera move smaller than a texel slides the maps by whole texels,
// leaving their contents unchanged (no shimmering).
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <set>

#include "gpu_fixture.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

// The default scene lit by its sun alone.
Scene sunlit_scene() {
  Scene scene = *builtin_scene("default");
  std::erase_if(scene.lights, [](const Light& l) { return l.type != LightType::Directional; });
  return scene;
}

TEST_F(GpuTest, EveryVisiblePixelFallsInACascade) {
  Renderer renderer(sunlit_scene());
  RenderSettings rs = testing::small_frame(192, 128, View::Cascades);
  for (int cascades = 1; cascades <= 4; ++cascades) {
    ShadowSettings shadow;
    shadow.map_size = 256;
    shadow.cascades = cascades;
    renderer.render(rs, shadow);
    const Image image = renderer.read_view();
    const LightShadowViews& views = renderer.shadow_views(0);
    ASSERT_EQ(static_cast<int>(views.views.size()), cascades);
    ASSERT_EQ(static_cast<int>(views.cascade_end.size()), cascades);
    float near_plane = 0.0f, far_plane = 0.0f;
    renderer.camera_depth_range(rs.width, rs.height, near_plane, far_plane);
    EXPECT_FLOAT_EQ(views.cascade_start, near_plane);
    EXPECT_FLOAT_EQ(views.cascade_end.back(), far_plane)
        << "the last cascade ends at the far plane";
    for (int c = 1; c < cascades; ++c) {
      EXPECT_GT(views.cascade_end[static_cast<std::size_t>(c)],
                views.cascade_end[static_cast<std::size_t>(c) - 1]);
      EXPECT_GT(views.views[static_cast<std::size_t>(c)].texel_world,
                views.views[static_cast<std::size_t>(c) - 1].texel_world);
    }
    int geometry = 0, uncovered = 0;
    std::set<std::tuple<int, int, int>> colours;
    for (int y = 0; y < rs.height; ++y) {
      for (int x = 0; x < rs.width; ++x) {
        const float* p = image.pixel(x, y);
        if (p[3] == 0.0f) continue;  // background
        ++geometry;
        if (p[0] + p[1] + p[2] == 0.0f) ++uncovered;
        colours.insert({int(p[0] * 20), int(p[1] * 20), int(p[2] * 20)});
      }
    }
    std::printf("%d cascades: %d of %d geometry pixels outside every cascade, %zu colours\n",
                cascades, uncovered, geometry, colours.size());
    EXPECT_GT(geometry, rs.width * rs.height / 2);
    EXPECT_EQ(uncovered, 0);
    EXPECT_GE(static_cast<int>(colours.size()), cascades) << "each cascade shades some pixels";
  }
}

// The light-space position of a view's map corner (clip (-1, -1)).
glm::vec2 map_origin(const LightView& v) {
  const glm::vec4 corner = glm::inverse(v.view_projection) * glm::vec4(-1.0f, -1.0f, 0.0f, 1.0f);
  return glm::vec2(v.view * (corner / corner.w));
}

TEST_F(GpuTest, SubTexelCameraMovesLeaveTheCascadeMapsUnchanged) {
  Renderer renderer(sunlit_scene());
  RenderSettings rs = testing::small_frame(128, 96);
  ShadowSettings shadow;
  shadow.map_size = 256;
  const Camera start = renderer.scene().camera;
  renderer.render(rs, shadow);
  const LightShadowViews before = renderer.shadow_views(0);
  std::vector<Image> maps_before;
  for (std::size_t c = 0; c < before.views.size(); ++c) {
    maps_before.push_back(renderer.read_shadow_view(static_cast<int>(c)));
  }
  // Moves of a fraction of the finest cascade's texel, sideways, up and
  // along the view, and a small turn.
  const float texel = before.views.front().texel_world;
  const glm::vec3 forward = glm::normalize(start.target - start.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, start.up));
  for (const glm::vec3& move : {0.3f * texel * right, 0.45f * texel * start.up,
                                0.7f * texel * forward, 0.2f * texel * (right + forward)}) {
    Camera camera = start;
    camera.position += move;
    camera.target += move;
    renderer.set_camera(camera);
    renderer.render(rs, shadow);
    const LightShadowViews& after = renderer.shadow_views(0);
    for (std::size_t c = 0; c < before.views.size(); ++c) {
      ASSERT_FLOAT_EQ(after.views[c].texel_world, before.views[c].texel_world) << "cascade " << c;
      const glm::vec2 shift =
          (map_origin(after.views[c]) - map_origin(before.views[c])) / before.views[c].texel_world;
      const glm::ivec2 whole(std::lround(shift.x), std::lround(shift.y));
      EXPECT_NEAR(shift.x, whole.x, 1e-2f) << "cascade " << c;
      EXPECT_NEAR(shift.y, whole.y, 1e-2f) << "cascade " << c;
      // Texel (x, y) now holds what texel (x, y) + shift held: the same
      // depths, compared where both maps see the scene.
      const Image map = renderer.read_shadow_view(static_cast<int>(c));
      const Image& old = maps_before[c];
      int compared = 0, changed = 0;
      double worst = 0.0;
      for (int y = 0; y < map.height; ++y) {
        for (int x = 0; x < map.width; ++x) {
          // Image rows run top to bottom, map rows (and light-space y) bottom to top.
          const int ox = x + whole.x, oy = y - whole.y;
          if (ox < 0 || oy < 0 || ox >= old.width || oy >= old.height) continue;
          const double d = std::abs(double(map.pixel(x, y)[0]) - old.pixel(ox, oy)[0]);
          ++compared;
          changed += d > 1e-4;
          worst = std::max(worst, d);
        }
      }
      std::printf("cascade %zu: shift (%d, %d) texels, %d of %d texels changed, largest %.2e\n", c,
                  whole.x, whole.y, changed, compared, worst);
      EXPECT_GT(compared, map.width * map.height / 2);
      EXPECT_LE(changed, compared / 2000) << "cascade " << c;
    }
  }
}

// A long wall under a low sun seen along its shadow through a narrow
// field of view: the camera's frustum slices are long and thin, so a
// cascade fitted to its own slice alone would miss the blend band in
// front of it, where the previous cascade blends into it.
Scene wall_scene() {
  return testing::TestScene("wall")
      .ground(200.0f)
      .box({0.0f, 1.0f, 0.0f}, {0.3f, 2.0f, 160.0f})
      .camera({4.0f, 4.0f, 70.0f}, {1.5f, 0.0f, -40.0f}, 8.0f)
      .light(testing::sun_light({1.0f, -0.8f, 0.15f}));
}

TEST_F(GpuTest, CascadeBlendBandsReadOnlyWhereTheNextCascadeHasData) {
  Renderer renderer(wall_scene());
  RenderSettings rs = testing::small_frame(160, 120);
  ShadowSettings shadow;
  shadow.map_size = 1024;
  shadow.cascades = 2;
  shadow.cascade_lambda = 0.3f;
  shadow.cascade_blend = 0.0f;
  renderer.render(rs, shadow);
  const Image unblended = renderer.read_view();
  shadow.cascade_blend = 0.5f;
  renderer.render(rs, shadow);
  const Image blended = renderer.read_view();
  // Pixels inside the shadow, two pixels or more from its edges: there
  // both cascades see the wall, whatever their resolutions (at the edges
  // the coarser cascade's texels may differ).
  auto inside_shadow = [&](int x, int y) {
    for (int dy = -2; dy <= 2; ++dy) {
      for (int dx = -2; dx <= 2; ++dx) {
        const int u = std::clamp(x + dx, 0, rs.width - 1), v = std::clamp(y + dy, 0, rs.height - 1);
        if (unblended.pixel(u, v)[3] == 0.0f || unblended.pixel(u, v)[0] > 0.5f) return false;
      }
    }
    return true;
  };
  int shadowed = 0, lighter = 0;
  float worst = 0.0f;
  for (int y = 0; y < rs.height; ++y) {
    for (int x = 0; x < rs.width; ++x) {
      if (!inside_shadow(x, y)) continue;
      ++shadowed;
      const float d = blended.pixel(x, y)[0] - unblended.pixel(x, y)[0];
      worst = std::max(worst, d);
      lighter += d > 0.02f;
    }
  }
  std::printf("%d shadowed pixels, %d lighter by more than 0.02 with the blend (largest %.3f)\n",
              shadowed, lighter, worst);
  EXPECT_GT(shadowed, rs.width * rs.height / 20);
  EXPECT_EQ(lighter, 0);
}

}  // namespace
}  // namespace penumbra
