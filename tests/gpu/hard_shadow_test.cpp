// Hard shadows on known geometry: a box above a plane, lit from above.
#include <glm/gtc/matrix_transform.hpp>
#include <optional>

#include "gpu_fixture.hpp"
#include "render/camera_depth.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr float kBoxHalf = 0.5f;
constexpr float kBoxBottom = 1.5f;

Scene box_above_plane(const Light& light) {
  return testing::TestScene("box above plane")
      .ground(12.0f)
      .box({0.0f, kBoxBottom + kBoxHalf, 0.0f}, glm::vec3(2.0f * kBoxHalf))
      .camera({0.0f, 9.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, 50.0f)
      .light(light);
}

// Where the camera ray through a pixel meets the plane y = 0, if it meets
// it before the box.
std::optional<glm::vec3> plane_point(const Renderer& r, int width, int height, int x, int y,
                                     float box_bottom = kBoxBottom) {
  const glm::dmat4 inverse =
      glm::inverse(glm::dmat4(r.camera_projection(width, height) * r.camera_view()));
  const glm::dvec2 ndc{(x + 0.5) / width * 2.0 - 1.0, 1.0 - (y + 0.5) / height * 2.0};
  glm::vec3 origin(position_from_depth(inverse, ndc, CAMERA_NEAR_DEPTH));
  glm::vec3 dir =
      glm::normalize(glm::vec3(position_from_depth(inverse, ndc, CAMERA_FAR_DEPTH)) - origin);
  if (dir.y >= 0.0f) return std::nullopt;
  // Slab test against the box.
  glm::vec3 lo{-kBoxHalf, box_bottom, -kBoxHalf}, hi{kBoxHalf, box_bottom + 2 * kBoxHalf, kBoxHalf};
  glm::vec3 t0 = (lo - origin) / dir, t1 = (hi - origin) / dir;
  glm::vec3 tmin = glm::min(t0, t1), tmax = glm::max(t0, t1);
  float enter = std::max({tmin.x, tmin.y, tmin.z}), leave = std::min({tmax.x, tmax.y, tmax.z});
  if (enter <= leave && leave > 0.0f) return std::nullopt;
  return origin + dir * (-origin.y / dir.y);
}

struct PlaneStats {
  int umbra = 0, umbra_shadowed = 0;  // points whose light path crosses the box
  int lit = 0, lit_darkened = 0;      // points well away from the shadow
};

// Classifies plane pixels by where the shadow must be: for a point p, the
// segment to the light crosses the box's footprint at the box's height.
PlaneStats measure(const Light& light, const ShadowSettings& shadow) {
  Scene scene = box_above_plane(light);
  Renderer renderer(scene);
  RenderSettings rs = testing::small_frame(256, 256);
  renderer.render(rs, shadow);
  Image image = renderer.read_view();
  PlaneStats stats;
  const float margin = 0.25f;  // world units, several texels of the maps used here
  for (int y = 0; y < rs.height; ++y) {
    for (int x = 0; x < rs.width; ++x) {
      auto p = plane_point(renderer, rs.width, rs.height, x, y);
      if (!p) continue;
      // Where the ray towards the light crosses the box's mid-height.
      glm::vec3 to_light = light.type == LightType::Spot ? glm::normalize(light.position - *p)
                                                         : -glm::normalize(light.direction);
      float t = (kBoxBottom + kBoxHalf - p->y) / to_light.y;
      glm::vec3 q = *p + to_light * t;
      float d = std::max(std::abs(q.x), std::abs(q.z));  // box half-extent metric
      float value = image.pixel(x, y)[0];
      if (d < kBoxHalf - margin) {
        ++stats.umbra;
        stats.umbra_shadowed += value < 0.5f;
      } else if (d > kBoxHalf + 2.0f * margin) {
        ++stats.lit;
        stats.lit_darkened += value < 0.99f;
      }
    }
  }
  return stats;
}

Light spot_above() {
  Light light;
  light.type = LightType::Spot;
  light.position = {0.0f, 8.0f, 0.0f};
  light.direction = {0.0f, -1.0f, 0.0f};
  light.cone_degrees = 40.0f;
  light.inner_cone_degrees = 35.0f;
  light.intensity = 60.0f;
  return light;
}

Light sun_above() {
  Light light;
  light.type = LightType::Directional;
  light.direction = glm::normalize(glm::vec3(0.15f, -1.0f, 0.1f));
  return light;
}

// A spot light whose axis meets the plane at a slant: its linear depth
// varies across the plane, as acne needs.
Light spot_slanted() {
  Light light = spot_above();
  light.position = {3.0f, 7.0f, 1.0f};
  light.direction = glm::normalize(-light.position);
  return light;
}

TEST_F(GpuTest, HardShadowUnderTheBoxAndNoAcneWithDefaultBiases) {
  for (const Light& light : {spot_above(), spot_slanted(), sun_above()}) {
    ShadowSettings shadow;
    shadow.technique = Technique::Hard;
    shadow.map_size = 512;
    PlaneStats s = measure(light, shadow);
    const double acne = double(s.lit_darkened) / s.lit;
    std::printf("%s light: umbra %d/%d shadowed, lit plane %d px, acne %.4f%%\n",
                light.type == LightType::Spot ? "spot" : "directional", s.umbra_shadowed, s.umbra,
                s.lit, 100.0 * acne);
    ASSERT_GT(s.umbra, 100);
    ASSERT_GT(s.lit, 10000);
    EXPECT_EQ(s.umbra_shadowed, s.umbra) << "pixels under the box must be in shadow";
    EXPECT_LT(acne, 0.001) << "shadow acne on the lit plane";
  }
}

// The biases are what prevents acne: without them it appears. (Not under
// spot_above(): a plane perpendicular to a spot light's axis has one
// linear depth everywhere, so it cannot shadow itself.)
TEST_F(GpuTest, WithoutBiasShadowAcneAppears) {
  for (const Light& light : {spot_slanted(), sun_above()}) {
    ShadowSettings shadow;
    shadow.technique = Technique::Hard;
    shadow.map_size = 512;
    shadow.constant_bias = 0.0f;
    shadow.slope_bias = 0.0f;
    shadow.normal_offset = 0.0f;
    PlaneStats s = measure(light, shadow);
    const double acne = double(s.lit_darkened) / s.lit;
    std::printf("%s light without bias: acne %.2f%%\n",
                light.type == LightType::Spot ? "spot" : "directional", 100.0 * acne);
    EXPECT_GT(acne, 0.05) << "expected visible acne with every bias at 0";
  }
}

TEST_F(GpuTest, TechniqueNoneCastsNoShadow) {
  ShadowSettings shadow;
  shadow.technique = Technique::None;
  shadow.map_size = 512;
  PlaneStats s = measure(spot_above(), shadow);
  EXPECT_EQ(s.umbra_shadowed, 0);
  EXPECT_EQ(s.lit_darkened, 0);
}

// No peter-panning: a box resting on the ground shadows the ground right
// up to its foot, with the default biases.
TEST_F(GpuTest, ContactShadowHasNoGapAtTheFoot) {
  Light light;
  light.type = LightType::Spot;
  light.position = {-6.0f, 6.0f, 0.0f};
  light.direction = glm::normalize(-light.position);
  light.cone_degrees = 30.0f;
  light.intensity = 60.0f;
  Scene scene = box_above_plane(light);
  scene.shapes[1].position.y = kBoxHalf;       // resting on the ground
  scene.camera.position = {5.0f, 4.0f, 3.0f};  // looking at the shadowed side
  Renderer renderer(scene);
  RenderSettings rs = testing::small_frame(512, 512);
  ShadowSettings shadow;
  shadow.map_size = 1024;
  renderer.render(rs, shadow);
  Image image = renderer.read_view();
  int samples = 0, lit = 0;
  for (int y = 0; y < rs.height; ++y) {
    for (int x = 0; x < rs.width; ++x) {
      auto p = plane_point(renderer, rs.width, rs.height, x, y, 0.0f);
      // Ground within 0.01 to 0.08 of the face away from the light.
      if (!p || p->x < kBoxHalf + 0.01f || p->x > kBoxHalf + 0.08f || std::abs(p->z) > 0.4f)
        continue;
      ++samples;
      lit += image.pixel(x, y)[0] > 0.5f;
    }
  }
  ASSERT_GT(samples, 50);
  EXPECT_EQ(lit, 0) << lit << " of " << samples << " ground points at the box's foot are lit";
}

}  // namespace
}  // namespace penumbra
