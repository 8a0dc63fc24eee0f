// Each light's source size is its own (Light::light_size): two spot lights
// of different sizes over two equal boxes cast penumbrae of different
// widths, in penumbra's renderer and in the traced reference alike;
// ShadowSettings' --light-size sets every spot light's size at once.
#include <cstdio>

#include "gpu_fixture.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/shadow_ray_tracer.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;
using testing::spot_light;

constexpr float kSmallSource = 0.1f;
constexpr float kLargeSource = 2.0f;
constexpr int kRays = 64;

// Two boxes floating 1 above the ground at x = -3 and x = 3, each under a
// spot light 6 above it shining straight down (its cone does not reach the
// other box): the penumbra around a box's shadow is about size / 5 wide.
Scene two_spot_lights(float left_size, float right_size) {
  testing::TestScene scene("two spot lights");
  scene.ground(16.0f, 8.0f).camera({0.0f, 10.0f, 7.0f}, {0.0f, 0.0f, 0.0f}, 50.0f);
  for (float x : {-3.0f, 3.0f}) {
    scene.box({x, 1.5f, 0.0f}, glm::vec3(1.0f));
    Light light = spot_light({x, 6.5f, 0.0f}, {x, 0.0f, 0.0f}, Light{}.cone_degrees,
                             Light{}.inner_cone_degrees);
    light.intensity = 30.0f;
    light.light_size = x < 0.0f ? left_size : right_size;
    scene.light(light);
  }
  return scene;
}

ShadowSettings pcss() {
  ShadowSettings s;
  s.technique = Technique::Pcss;
  s.map_size = 1024;
  return s;
}

RenderSettings shadow_of(int light) {
  RenderSettings rs = testing::small_frame(256, 160);
  rs.light_index = light;
  return rs;
}

// Ground pixels in the light's half of the scene whose shadow factor is
// strictly between umbra and lit: the penumbra's area in pixels.
int penumbra_pixels(const Image& image, const SurfacePoints& surfaces, int light) {
  int count = 0;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    if (!surfaces.covered[i] || surfaces.position[i].y > 1e-3f) continue;
    if ((surfaces.position[i].x < 0.0f) != (light == 0)) continue;
    const float v = image.rgba[4 * i];
    if (v > 0.1f && v < 0.9f) ++count;
  }
  return count;
}

// The image with only the ground pixels in the light's half of the scene
// left to compare (alpha 1): where the box's shadow and its penumbra fall.
// The boxes' own sides are left out: lit by part of a wide source, they
// differ from the techniques', which light a face by the source's centre.
Image ground_of(Image image, const SurfacePoints& surfaces, int light) {
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const bool ground = surfaces.covered[i] && surfaces.position[i].y <= 1e-3f &&
                        (surfaces.position[i].x < 0.0f) == (light == 0);
    if (!ground) image.rgba[4 * i + 3] = 0.0f;
  }
  return image;
}

struct LightResult {
  int penumbra = 0;
  double rmse = 0.0;        // against the traced reference of the same light
  double rmse_other = 0.0;  // against the reference traced with the other light's size
};

LightResult measure(const Scene& scene, const ShadowSettings& settings, int light,
                    float other_size) {
  Renderer renderer(scene);
  renderer.render(shadow_of(light), settings);
  const SurfacePoints surfaces = renderer.read_surfaces();
  const Image image = ground_of(renderer.read_view(), surfaces, light);
  const ShadowRayTracer tracer(renderer.mesh());
  const Light& l = scene.lights[static_cast<std::size_t>(light)];
  const Image traced =
      tracer.trace(surfaces, make_reference_light(l, renderer.light_view(light), settings), kRays);
  Light other = l;
  other.light_size = other_size;
  ShadowSettings own_sizes = settings;
  own_sizes.light_size = SourceSizeOverride(Light{}.light_size);
  const Image traced_other = tracer.trace(
      surfaces, make_reference_light(other, renderer.light_view(light), own_sizes), kRays);
  return {penumbra_pixels(image, surfaces, light), compare_shadow(image, traced).rmse,
          compare_shadow(image, traced_other).rmse};
}

TEST_F(GpuTest, TwoSpotLightsOfDifferentSizesCastTwoPenumbrae) {
  const Scene scene = two_spot_lights(kSmallSource, kLargeSource);
  const LightResult small = measure(scene, pcss(), 0, kLargeSource);
  const LightResult large = measure(scene, pcss(), 1, kSmallSource);
  std::printf("penumbra pixels: %.2f-wide light %d, %.2f-wide light %d\n", kSmallSource,
              small.penumbra, kLargeSource, large.penumbra);
  std::printf(
      "RMSE against the traced reference of its own size: %.4f, %.4f; of the other's: "
      "%.4f, %.4f\n",
      small.rmse, large.rmse, small.rmse_other, large.rmse_other);
  // Similar triangles: penumbrae 0.02 and 0.4 wide around a 1x1 shadow.
  EXPECT_GT(large.penumbra, 4 * std::max(small.penumbra, 1));
  // The reference traces each light's own source: the other size's
  // reference fits the image worse.
  EXPECT_LT(large.rmse, 0.75 * large.rmse_other);
  EXPECT_LT(small.rmse, 0.75 * small.rmse_other);

  // One size for every light (both lights as large, or as small): each
  // light's error is what it is with its size given to both.
  const LightResult one_large =
      measure(two_spot_lights(kLargeSource, kLargeSource), pcss(), 1, kSmallSource);
  const LightResult one_small =
      measure(two_spot_lights(kSmallSource, kSmallSource), pcss(), 0, kLargeSource);
  std::printf("RMSE with one size for both lights: %.4f (small), %.4f (large)\n", one_small.rmse,
              one_large.rmse);
  EXPECT_LE(small.rmse, one_small.rmse * 1.05 + 1e-3);
  EXPECT_LE(large.rmse, one_large.rmse * 1.05 + 1e-3);
}

TEST_F(GpuTest, LightSizeSettingSetsEverySpotLight) {
  const Scene scene = two_spot_lights(kSmallSource, kLargeSource);
  ShadowSettings every = pcss();
  every.light_size = kLargeSource;  // as --light-size 2 does
  const LightResult small_made_large = measure(scene, every, 0, kSmallSource);
  const LightResult large = measure(scene, pcss(), 1, kSmallSource);
  std::printf("penumbra pixels under --light-size %.2f: light 0 %d (light 1 as its own: %d)\n",
              kLargeSource, small_made_large.penumbra, large.penumbra);
  EXPECT_GT(small_made_large.penumbra, large.penumbra * 3 / 4);
  EXPECT_LT(small_made_large.penumbra, large.penumbra * 5 / 4);
  // The reference follows the setting too.
  EXPECT_LT(small_made_large.rmse, 0.75 * small_made_large.rmse_other);
}

}  // namespace
}  // namespace penumbra
