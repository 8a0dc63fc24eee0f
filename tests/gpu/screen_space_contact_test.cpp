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

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr float kSlabHeight = 0.02f;
constexpr float kSlabDepth = 0.6f;  // along z: the light comes from -z
// The light rises 8 degrees above the ground at the slab: its shadow is
// kSlabHeight / tan(8 degrees), about 0.14, long (within the first half of
// the march's default length, before its fade).
constexpr float kElevation = 0.14f;  // tan(8 degrees)

Scene slab_scene(LightType type) {
  Scene scene;
  scene.name = "slab";
  scene.materials = {{"grey", {0.7f, 0.7f, 0.7f}, {0.0f, 0.0f, 0.0f}, 8.0f}};
  Shape ground;
  ground.kind = ShapeKind::Plane;
  ground.size = {8.0f, 0.0f, 8.0f};
  scene.shapes.push_back(ground);
  Shape slab;
  slab.kind = ShapeKind::Box;
  slab.position = {0.0f, 0.5f * kSlabHeight, 0.0f};
  slab.size = {1.2f, kSlabHeight, kSlabDepth};
  scene.shapes.push_back(slab);
  // From the shadow's side, looking down at the strip behind the slab.
  scene.camera.position = {0.0f, 0.8f, 1.3f};
  scene.camera.target = {0.0f, 0.0f, 0.35f};
  scene.camera.fov_y_degrees = 30.0f;
  Light light;
  light.type = type;
  light.position = {0.0f, 5.0f * kElevation, -5.0f};
  light.direction = glm::normalize(glm::vec3(0.0f, -kElevation, 1.0f));
  light.cone_degrees = 25.0f;
  light.inner_cone_degrees = 20.0f;
  scene.lights.push_back(light);
  return scene;
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
  RenderSettings rs;
  rs.width = 192;
  rs.height = 108;
  rs.view = View::Shadow;
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
                         [](const ::testing::TestParamInfo<LightType>& info) {
                           return info.param == LightType::Spot          ? std::string("Spot")
                                  : info.param == LightType::Directional ? std::string("Sun")
                                                                         : std::string("Point");
                         });

}  // namespace
}  // namespace penumbra
