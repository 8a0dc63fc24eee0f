// The camera's depth buffer is reversed-Z (render/camera_depth.hpp): a
// point rebuilt from it keeps float32's relative precision at every
// distance, and within the error bound the reference tracer offsets its
// rays by (render/depth_position_error.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gpu_fixture.hpp"
#include "render/camera_depth.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr int kSize = 96;

// A ground plane (y = 0) seen from `camera` looking at `target` (`up`
// when looking straight down), and a speck `speck_distance` in front of
// the camera that pulls the fitted near plane to its floor, 1e-4 of the
// far one (the speck itself is clipped).
Scene ground_scene(glm::vec3 camera, glm::vec3 target, glm::vec3 up, float width, float depth,
                   glm::vec3 ground_centre, float speck_distance) {
  Scene scene = testing::TestScene("far ground")
                    .ground(width, depth, ground_centre)
                    .box(camera + glm::normalize(target - camera) * speck_distance,
                         glm::vec3(speck_distance * 0.1f))
                    .camera(camera, target, 40.0f)
                    .light(testing::sun_light({0.0f, -1.0f, 0.0f}));
  scene.camera.up = up;
  return scene;
}

struct GroundErrors {
  long ground = 0;            // pixels that see the ground
  long outside_bound = 0;     // rebuilt farther off the plane than their error bound
  double worst_relative = 0;  // |y| / distance to the camera
  double largest_bound = 0;   // error bound / distance to the camera
  float near_plane = 0, far_plane = 0;
};

// Every ground pixel rebuilt from the depth buffer (Renderer::read_surfaces,
// the points the reference traces from) against the plane y = 0.
GroundErrors ground_errors(const Scene& scene) {
  Renderer renderer(scene);
  renderer.render(testing::small_frame(kSize, kSize, View::Albedo), ShadowSettings{});
  GroundErrors e;
  renderer.camera_depth_range(kSize, kSize, e.near_plane, e.far_plane);
  const SurfacePoints s = renderer.read_surfaces();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.covered[i] || s.normal[i].y < 0.999f) continue;
    ++e.ground;
    const double distance =
        glm::distance(glm::dvec3(s.position[i]), glm::dvec3(scene.camera.position));
    const double off = std::abs(double(s.position[i].y));
    e.worst_relative = std::max(e.worst_relative, off / distance);
    e.largest_bound = std::max(e.largest_bound, double(s.position_error[i]) / distance);
    e.outside_bound += off > s.position_error[i];
  }
  return e;
}

// Looking straight down at ground 100 units away with the near plane at
// 1e-4 of the far one: standard-Z's depth there is 1 - 1e-4 (z - n) / z,
// where a float32 step of 2^-24 is 6e-4 of the distance; reversed-Z's is
// n (f - z) / (z (f - n)), about 1e-6, whose steps are 2^-24 of itself.
TEST_F(GpuTest, FarGroundRebuildsWithinAMillionthOfItsDistance) {
  const GroundErrors e =
      ground_errors(ground_scene({0.0f, 100.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f},
                                 400.0f, 400.0f, glm::vec3(0.0f), 0.004f));
  std::printf(
      "near %.4g far %.4g: ground off its plane by up to %.2e of the distance; "
      "bound up to %.2e of it\n",
      e.near_plane, e.far_plane, e.worst_relative, e.largest_bound);
  EXPECT_NEAR(e.near_plane / e.far_plane, 1e-4, 1e-7) << "the near plane at its floor";
  EXPECT_EQ(e.ground, kSize * kSize);
  EXPECT_LT(e.worst_relative, 1e-6);
  EXPECT_LT(e.largest_bound, 2e-6) << "the bound is a few 2^-24 of the distance";
  EXPECT_EQ(e.outside_bound, 0) << "ground points farther off the plane than their error bound";
}

// A long ground seen at grazing angles (scenes/long_plane.json's, 260
// units deep from 2.5 units above it): its triangles span tens of units
// of depth, and the points rebuilt from the depth interpolated across
// them stay within their bound all the way to the far end.
TEST_F(GpuTest, GrazingGroundStaysWithinItsErrorBound) {
  const GroundErrors e =
      ground_errors(ground_scene({0.0f, 2.5f, 24.0f}, {0.0f, 0.6f, -20.0f}, {0.0f, 1.0f, 0.0f},
                                 40.0f, 260.0f, {0.0f, 0.0f, -100.0f}, 0.02f));
  std::printf(
      "near %.4g far %.4g: ground off its plane by up to %.2e of the distance; "
      "bound up to %.2e of it\n",
      e.near_plane, e.far_plane, e.worst_relative, e.largest_bound);
  EXPECT_GT(e.ground, kSize * kSize / 3);
  EXPECT_EQ(e.outside_bound, 0) << "ground points farther off the plane than their error bound";
}

}  // namespace
}  // namespace penumbra
