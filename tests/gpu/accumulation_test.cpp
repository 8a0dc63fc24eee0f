// Accumulated soft shadows converge to the traced reference: hard shadows
// from points spread over the source, weighted as the reference weighs
// them.
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_fixture.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/traced_reference.hpp"
#include "render/accumulation.hpp"
#include "render/accumulator.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

// On the default scene with a 1.5-wide spot light, 32 dithered hard
// sub-frames come within 0.018 RMSE of the traced reference (measured
// 0.0148 at this small size, most of it the dither's noise), under a
// quarter of one hard frame's error (0.087), and the renderer's lights
// are left as they were.
TEST_F(GpuTest, AccumulatedHardShadowsApproachTheReference) {
  const Scene scene = *builtin_scene("default");
  Renderer renderer(scene);
  RenderSettings rs;
  rs.width = 160;
  rs.height = 96;
  rs.view = View::Shadow;
  ShadowSettings shadow;
  shadow.technique = Technique::Hard;
  shadow.map_size = 1024;
  shadow.light_size = 1.5f;
  const TracedReference reference = traced_reference(renderer, rs, shadow, 256, "");

  renderer.render(rs, shadow);
  const Image single = renderer.read_view();
  shadow.accumulate = 32;
  const Image accumulated = render_accumulated(renderer, rs, shadow);
  const double single_rmse = compare_shadow(single, reference.image).rmse;
  const double accumulated_rmse = compare_shadow(accumulated, reference.image).rmse;
  std::printf("RMSE against the reference: one hard frame %.4f, 32 accumulated %.4f\n", single_rmse,
              accumulated_rmse);
  EXPECT_LT(accumulated_rmse, 0.018);
  EXPECT_LT(accumulated_rmse, 0.25 * single_rmse);
  EXPECT_EQ(renderer.scene().lights, scene.lights);
}

// A sub-frame of the weighted shadow view writes (lit, lit w, w) with w
// what its point of the source sends the pixel, cos theta_source
// cos theta_receiver / d^2 (the traced reference's weight), and the
// Accumulator's result is the weighted mean: checked pixel by pixel on the
// ground under a spot light looking straight down, where every pixel is lit.
TEST_F(GpuTest, SubFramesCarryTheirSourceWeights) {
  Scene scene;
  scene.materials.push_back({});
  Shape ground;
  ground.kind = ShapeKind::Plane;
  ground.size = glm::vec3(20.0f);
  scene.shapes.push_back(ground);
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {0.0f, 4.0f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.cone_degrees = 80.0f;
  spot.inner_cone_degrees = 70.0f;
  scene.lights = {spot};
  scene.camera.position = {0.0f, 6.0f, 3.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  Renderer renderer(scene);
  RenderSettings rs;
  rs.width = 48;
  rs.height = 32;
  rs.view = View::Shadow;
  ShadowSettings shadow;
  shadow.technique = Technique::Hard;
  shadow.map_size = 256;
  shadow.light_size = 1.5f;
  shadow.accumulate = 4;

  Accumulator accumulator;
  std::vector<double> weight_sum(static_cast<std::size_t>(rs.width) * rs.height, 0.0);
  int checked = 0;
  for (int k = 0; k < shadow.accumulate; ++k) {
    render_subframe(renderer, scene.lights, rs, shadow, {}, k);
    const SourceSample sample = source_sample(spot, shadow, k, shadow.accumulate, 0);
    const Image raw = renderer.read_view();
    const SurfacePoints surfaces = renderer.read_surfaces();
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
      if (!surfaces.covered[i]) continue;
      const glm::vec3 d = sample.light.position - surfaces.position[i];
      const glm::vec3 w = glm::normalize(d);
      const float expected =
          glm::dot(surfaces.normal[i], w) * -glm::dot(sample.normal, w) / glm::dot(d, d);
      ASSERT_EQ(raw.rgba[4 * i], 1.0f) << "pixel " << i << " should be lit";
      EXPECT_NEAR(raw.rgba[4 * i + 2], expected, 1e-3f * expected) << "pixel " << i;
      EXPECT_EQ(raw.rgba[4 * i + 1], raw.rgba[4 * i + 2]);
      weight_sum[i] += raw.rgba[4 * i + 2];
      ++checked;
    }
    accumulator.add(renderer.view_source());
  }
  EXPECT_GT(checked, shadow.accumulate * rs.width * rs.height / 2);
  // All lit: the weighted mean is 1 wherever a weight reached the pixel.
  const Image result = read_view_source(accumulator.result(true));
  for (std::size_t i = 0; i < weight_sum.size(); ++i) {
    if (weight_sum[i] > 0.0) {
      EXPECT_FLOAT_EQ(result.rgba[4 * i], 1.0f) << "pixel " << i;
    }
  }
}

// The Accumulator's plain mean is the mean of the sub-frames' views.
TEST_F(GpuTest, AccumulatedFinalViewIsTheMeanOfItsSubFrames) {
  const Scene scene = *builtin_scene("default");
  Renderer renderer(scene);
  RenderSettings rs;
  rs.width = 64;
  rs.height = 40;
  ShadowSettings shadow;
  shadow.technique = Technique::Hard;
  shadow.map_size = 512;
  shadow.light_size = 1.0f;
  shadow.accumulate = 3;
  std::vector<double> mean(static_cast<std::size_t>(rs.width) * rs.height * 4, 0.0);
  for (int k = 0; k < shadow.accumulate; ++k) {
    render_subframe(renderer, scene.lights, rs, shadow, {}, k);
    const Image image = renderer.read_view();
    for (std::size_t i = 0; i < mean.size(); ++i) mean[i] += image.rgba[i] / shadow.accumulate;
  }
  renderer.set_lights(scene.lights);
  const Image accumulated = render_accumulated(renderer, rs, shadow);
  double largest = 0.0;
  for (std::size_t i = 0; i < mean.size(); ++i) {
    largest = std::max(largest, std::abs(mean[i] - accumulated.rgba[i]));
  }
  EXPECT_LT(largest, 1e-5);
  EXPECT_EQ(renderer.scene().lights, scene.lights);
}

}  // namespace
}  // namespace penumbra
