// The ray-traced reference against the rasterized pipeline: the surface
// points read back from the G-buffer, and the hard shadow of a fine map
// against the traced hard shadow.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gpu_fixture.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/shadow_ray_tracer.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

RenderSettings small_view(int light) {
  RenderSettings rs = testing::small_frame(192, 128);
  rs.light_index = light;
  return rs;
}

// Ground pixels (normal up, near y = 0) rebuild to points on the ground,
// and every covered pixel lies within the scene's bounds.
TEST_F(GpuTest, SurfacePointsLieOnTheScene) {
  Renderer renderer(*builtin_scene("default"));
  renderer.render(small_view(0), ShadowSettings{});
  const SurfacePoints s = renderer.read_surfaces();
  ASSERT_EQ(s.width, 192);
  ASSERT_EQ(s.height, 128);
  const Bounds bounds = renderer.mesh().bounds();
  long covered = 0, ground = 0, outside_bound = 0;
  double worst_ground = 0.0, worst_ratio = 0.0, largest_bound = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.covered[i]) continue;
    ++covered;
    const glm::vec3 p = s.position[i];
    EXPECT_TRUE(glm::all(glm::greaterThan(p, bounds.min - 1e-3f)) &&
                glm::all(glm::lessThan(p, bounds.max + 1e-3f)))
        << p.x << " " << p.y << " " << p.z;
    EXPECT_NEAR(glm::length(s.normal[i]), 1.0f, 1e-4f);
    if (s.normal[i].y > 0.999f && p.y < 0.1f) {
      ++ground;
      worst_ground = std::max(worst_ground, std::abs(double(p.y)));
      // The rebuilt point lies within its error bound of the ground's plane
      // (shadow rays start that far above it).
      const double ratio = std::abs(double(p.y)) / s.position_error[i];
      worst_ratio = std::max(worst_ratio, ratio);
      largest_bound = std::max(largest_bound, double(s.position_error[i]));
      outside_bound += ratio > 1.0;
    }
  }
  EXPECT_GT(ground, covered / 2) << "the ground fills most of the default view";
  // The depth buffer's rounding, a few millionths of the distance to the
  // camera.
  std::printf(
      "ground pixels off the ground by up to %.2e, %.2f of their error bound (at most %.2e)\n",
      worst_ground, worst_ratio, largest_bound);
  EXPECT_LT(worst_ground, 1e-4);
  EXPECT_EQ(outside_bound, 0) << "ground points farther off the plane than their error bound";
}

// A 4096^2 map's hard shadow agrees with the traced hard shadow on at
// least 99 % of the pixels, and every pixel where they disagree lies on a
// shadow edge of the traced image (the map's texels are a few
// thousandths of a unit wide; the view's pixels are about 0.06).
TEST_F(GpuTest, TracedHardShadowAgreesWithAFineShadowMap) {
  const Scene scene = *builtin_scene("default");
  Renderer renderer(scene);
  ShadowSettings hard;
  hard.map_size = 4096;
  hard.light_size = 0.0f;  // point lights: the traced hard shadow
  hard.sun_angle = 0.0f;
  const ShadowRayTracer tracer(renderer.mesh());
  for (int light = 0; light < 2; ++light) {
    renderer.render(small_view(light), hard);
    Image technique = renderer.read_view();
    const Image traced =
        tracer.trace(renderer.read_surfaces(),
                     make_reference_light(scene.lights[static_cast<std::size_t>(light)],
                                          renderer.light_view(light), hard),
                     1);
    long compared = 0, disagree = 0, off_edge = 0;
    for (int y = 0; y < traced.height; ++y) {
      for (int x = 0; x < traced.width; ++x) {
        if (traced.pixel(x, y)[3] < 0.5f || technique.pixel(x, y)[3] < 0.5f) continue;
        ++compared;
        const float t = traced.pixel(x, y)[0];
        if (std::abs(technique.pixel(x, y)[0] - t) < 0.5f) continue;
        ++disagree;
        // An edge: a neighbour within two pixels that the trace judges
        // differently, or that sees other geometry or none.
        bool edge = false;
        for (int dy = -2; dy <= 2 && !edge; ++dy) {
          for (int dx = -2; dx <= 2 && !edge; ++dx) {
            const int nx = std::clamp(x + dx, 0, traced.width - 1);
            const int ny = std::clamp(y + dy, 0, traced.height - 1);
            const float* n = traced.pixel(nx, ny);
            edge = n[3] < 0.5f || std::abs(n[0] - t) > 0.5f;
          }
        }
        off_edge += !edge;
      }
    }
    const ShadowMetrics m = compare_shadow(technique, traced);
    std::printf("light %d: %ld of %ld pixels disagree (%.3f%%), %ld off edges; MAE %.5f\n", light,
                disagree, compared, 100.0 * disagree / compared, off_edge, m.mean_absolute_error);
    EXPECT_GT(compared, 192 * 128 / 4);
    EXPECT_LE(disagree, compared / 100) << "light " << light;
    EXPECT_EQ(off_edge, 0) << "light " << light;
  }
}

}  // namespace
}  // namespace penumbra
