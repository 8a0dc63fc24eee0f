// --contact-shadows: a thin slab lying on the ground, lit at a grazing
// angle. Its shadow on the ground is a strip a few slab-heights long; the
// shadow map's slope-scaled bias at that angle is larger than the depth
// between the slab and the ground there, so every technique lets light
// under it (the contact line is lit where the traced reference is dark).
// The march through the camera's depth buffer towards the light finds the
// slab's face and darkens the strip as the reference does, for spot, sun
// and point lights, without darkening what the reference lights.
#include <cmath>
#include <cstdio>
#include <string>

#include "gpu_fixture.hpp"
#include "reference/traced_reference.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;
using testing::point_light;
using testing::small_frame;
using testing::spot_light;
using testing::sun_light;
using testing::TestScene;

constexpr float kSlabHeight = 0.02f;
constexpr float kSlabDepth = 0.6f;  // along z: the light comes from -z
// The light rises 8 degrees above the ground at the slab: its shadow is
// kSlabHeight / tan(8 degrees), about 0.14, long (within the first half of
// the march's default length, before its fade).
constexpr float kElevation = 0.14f;  // tan(8 degrees)

// A thin slab on the ground, seen from its shadow's side; the light comes
// from -z, kElevation above the ground at the slab.
Scene slab_scene(LightType type) {
  const glm::vec3 source(0.0f, 5.0f * kElevation, -5.0f);
  const Light light = type == LightType::Spot ? spot_light(source, glm::vec3(0.0f), 25.0f, 20.0f)
                      : type == LightType::Directional ? sun_light(-source)
                                                       : point_light(source, 30.0f);
  return TestScene("slab")
      .ground(8.0f)
      .box({0.0f, 0.5f * kSlabHeight, 0.0f}, {1.2f, kSlabHeight, kSlabDepth})
      .camera({0.0f, 0.8f, 1.3f}, {0.0f, 0.0f, 0.35f}, 30.0f)
      .light(light);
}

struct StripErrors {
  int strip = 0;         // ground pixels the reference shadows behind the slab
  double strip_lit = 0;  // the technique's mean there (the reference's is 0)
  int lit = 0;           // pixels the reference lights
  int darkened = 0;      // of them, darker than the reference by more than 0.5
};

StripErrors strip_errors(const Image& image, const Image& reference, const SurfacePoints& points) {
  StripErrors e;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      if (!points.covered[i] || reference.pixel(x, y)[3] < 0.5f) continue;
      const float ref = reference.pixel(x, y)[0];
      const float value = image.pixel(x, y)[0];
      const glm::vec3 p = points.position[i];
      const bool behind = p.z > 0.5f * kSlabDepth && std::abs(p.x) < 0.5f && p.y < 1e-3f;
      if (behind && ref < 0.01f) {
        ++e.strip;
        e.strip_lit += value;
      }
      if (ref > 0.99f) {
        ++e.lit;
        e.darkened += ref - value > 0.5f;
      }
    }
  }
  if (e.strip > 0) e.strip_lit /= e.strip;
  return e;
}

class ScreenSpaceContactTest : public GpuTest, public ::testing::WithParamInterface<LightType> {};

TEST_P(ScreenSpaceContactTest, DarkenTheContactLineTheMapLetsLightUnder) {
  Renderer renderer(slab_scene(GetParam()));
  const RenderSettings rs = small_frame(192, 108);
  ShadowSettings base;
  base.map_size = 256;
  base.light_size = 0.0f;  // a point source: the reference's shadow is binary
  base.sun_angle = 0.0f;
  base.cascades = 1;  // the sun's one map spans the view, as a spot light's does
  renderer.render(rs, base);
  const TracedReference reference = traced_reference(renderer, rs, base, 1, "");
  const SurfacePoints points = renderer.read_surfaces();
  for (const Technique technique : {Technique::Hard, Technique::Pcss, Technique::Vsm}) {
    for (const bool contact : {false, true}) {
      ShadowSettings shadow = base;
      shadow.technique = technique;
      shadow.contact_shadows = contact;
      renderer.render(rs, shadow);
      const StripErrors e = strip_errors(renderer.read_view(), reference.image, points);
      const std::string name = std::string(enum_name<Technique>(kTechniqueNames, technique)) +
                               (contact ? " --contact-shadows" : "");
      std::printf("%-30s strip of %d px: mean %.3f (reference 0); %d of %d lit px darkened\n",
                  name.c_str(), e.strip, e.strip_lit, e.darkened, e.lit);
      EXPECT_GT(e.strip, 150) << name;
      if (contact) {
        EXPECT_LT(e.strip_lit, 0.25) << name;
        EXPECT_LT(e.darkened, e.lit / 500) << name;
      } else {
        EXPECT_GT(e.strip_lit, 0.3) << name << ": the map no longer lets light under the slab";
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(LightTypes, ScreenSpaceContactTest,
                         ::testing::Values(LightType::Spot, LightType::Directional,
                                           LightType::Point),
                         testing::light_type_name);

}  // namespace
}  // namespace penumbra
