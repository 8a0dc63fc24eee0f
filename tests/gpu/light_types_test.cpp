// Every technique (and filter) on a point light's cube and on a cascaded
// directional light: renders without GL errors (the fixture fails a test on
// any), and the ground under a caster is darker than the open ground.
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>

#include "gpu_fixture.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr float kBoxHalf = 0.5f;
constexpr glm::vec3 kBoxCenter{0.0f, 1.5f, 0.0f};

struct Combination {
  LightType light;
  Technique technique;
  Filter filter;
  bool soft;
};

Scene box_above_ground(LightType type) {
  return testing::TestScene("box above ground")
      .ground(14.0f)
      .box(kBoxCenter, glm::vec3(2.0f * kBoxHalf))
      .camera({0.0f, 8.0f, 6.0f}, {0.0f, 0.0f, 0.0f}, 50.0f)
      .light(testing::overhead_light(type));
}

// Whether the segment from p towards the light passes through the box
// grown by `grow`.
bool behind_box(const Light& light, const glm::vec3& p, float grow) {
  const glm::vec3 to_light = light.type != LightType::Directional
                                 ? light.position - p
                                 : -8.0f * glm::normalize(light.direction);
  const glm::vec3 lo = kBoxCenter - (kBoxHalf + grow), hi = kBoxCenter + (kBoxHalf + grow);
  float enter = 0.0f, leave = 1.0f;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(to_light[a]) < 1e-9f) {
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
      continue;
    }
    float t0 = (lo[a] - p[a]) / to_light[a], t1 = (hi[a] - p[a]) / to_light[a];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave;
}

class LightTypeTest : public GpuTest, public ::testing::WithParamInterface<Combination> {};

TEST_P(LightTypeTest, ShadowUnderTheCasterIsDarkerThanTheOpenGround) {
  const Combination c = GetParam();
  const Scene scene = box_above_ground(c.light);
  Renderer renderer(scene);
  ShadowSettings shadow;
  shadow.technique = c.technique;
  shadow.filter = c.filter;
  shadow.soft = c.soft;
  shadow.map_size = 256;
  shadow.light_size = 0.2f;
  RenderSettings rs = testing::small_frame(128, 128, View::Final);
  renderer.render(rs, shadow);  // the lit image, for GL errors
  rs.view = View::Shadow;
  renderer.render(rs, shadow);
  const Image image = renderer.read_view();
  const SurfacePoints surfaces = renderer.read_surfaces();
  double umbra_sum = 0.0, lit_sum = 0.0;
  int umbra = 0, lit = 0;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    if (!surfaces.covered[i] || surfaces.position[i].y > 1e-3f) continue;  // ground only
    const float value = image.rgba[4 * i];
    ASSERT_TRUE(std::isfinite(value));
    if (behind_box(scene.lights[0], surfaces.position[i], -0.2f)) {
      umbra_sum += value;
      ++umbra;
    } else if (!behind_box(scene.lights[0], surfaces.position[i], 0.6f)) {
      lit_sum += value;
      ++lit;
    }
  }
  ASSERT_GT(umbra, 20);
  ASSERT_GT(lit, 1000);
  const double umbra_mean = umbra_sum / umbra, lit_mean = lit_sum / lit;
  std::printf("umbra %.3f (%d px), open ground %.3f (%d px)\n", umbra_mean, umbra, lit_mean, lit);
  if (c.technique == Technique::None) {
    EXPECT_EQ(umbra_mean, 1.0);
  } else {
    EXPECT_LT(umbra_mean, 0.2);
    EXPECT_GT(lit_mean, 0.97);
  }
}

// A point light's irradiance falls off as I / d^2: the light it adds to a
// matte ground (the image with the light on minus the one with it off) is
// albedo * I * cos(theta) / d^2 at every pixel (to the 8-bit sRGB storage of
// the albedo 0.7: 1e-4).
TEST_F(GpuTest, PointLightFallsOffWithTheInverseSquareOfTheDistance) {
  Scene scene = box_above_ground(LightType::Point);
  scene.shapes.pop_back();  // the ground alone
  const float albedo = scene.materials[0].albedo.r;
  const Light light = scene.lights[0];
  Renderer renderer(scene);
  RenderSettings rs;
  rs.width = 96;
  rs.height = 96;
  ShadowSettings shadow;
  shadow.technique = Technique::None;
  SsaoSettings ssao;
  ssao.enabled = false;
  renderer.render(rs, shadow, ssao);
  const Image lit = renderer.read_view();
  const SurfacePoints surfaces = renderer.read_surfaces();
  Light off = light;
  off.intensity = 0.0f;
  renderer.set_lights({off});
  renderer.render(rs, shadow, ssao);
  const Image unlit = renderer.read_view();
  double worst = 0.0;
  int pixels = 0;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    if (!surfaces.covered[i]) continue;
    const glm::vec3 d = light.position - surfaces.position[i];
    const double cos_theta = glm::normalize(d).y;
    const double expected = albedo * light.intensity * cos_theta / glm::dot(d, d);
    const double added = double(lit.rgba[4 * i]) - unlit.rgba[4 * i];
    worst = std::max(worst, std::abs(added - expected) / expected);
    ++pixels;
  }
  std::printf("inverse-square fall-off: largest relative error %.2e over %d pixels\n", worst,
              pixels);
  ASSERT_GT(pixels, rs.width * rs.height / 2);
  EXPECT_LT(worst, 1e-3);
}

// Several lights of different types: each reads its own views (a point
// light's six, a sun's cascades, a spot light's one, numbered across the
// lights), and its shadow falls where its own geometry puts it.
TEST_F(GpuTest, SeveralLightsEachReadTheirOwnViews) {
  Scene scene = box_above_ground(LightType::Point);
  Light sun = scene.lights[0];
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, 0.2f));
  Light spot = scene.lights[0];
  spot.type = LightType::Spot;
  spot.position = {-1.0f, 5.0f, -1.5f};
  spot.direction = glm::normalize(glm::vec3(0.0f) - spot.position);
  spot.cone_degrees = 50.0f;
  scene.lights.push_back(sun);
  scene.lights.push_back(spot);
  Renderer renderer(scene);
  ShadowSettings shadow;
  shadow.technique = Technique::Pcf;
  shadow.map_size = 256;
  shadow.cascades = 2;
  RenderSettings rs = testing::small_frame(128, 128, View::Final);
  renderer.render(rs, shadow);
  EXPECT_EQ(renderer.first_view(0), 0);
  EXPECT_EQ(renderer.first_view(1), 6);
  EXPECT_EQ(renderer.first_view(2), 8);
  EXPECT_EQ(renderer.shadow_views(2).views.size(), 1u);
  rs.view = View::Shadow;
  for (int i = 0; i < 3; ++i) {
    rs.light_index = i;
    renderer.render(rs, shadow);
    const Image image = renderer.read_view();
    const SurfacePoints surfaces = renderer.read_surfaces();
    const Light& light = scene.lights[static_cast<std::size_t>(i)];
    int umbra = 0, umbra_dark = 0, lit = 0, lit_dark = 0;
    for (std::size_t p = 0; p < surfaces.size(); ++p) {
      if (!surfaces.covered[p] || surfaces.position[p].y > 1e-3f) continue;
      const glm::vec3 q = surfaces.position[p];
      if (light.type == LightType::Spot &&
          glm::dot(glm::normalize(q - light.position), light.direction) <
              std::cos(glm::radians(light.cone_degrees))) {
        continue;  // outside the spot's cone: no shadow map there
      }
      const float value = image.rgba[4 * p];
      if (behind_box(light, q, -0.2f)) {
        ++umbra;
        umbra_dark += value < 0.5f;
      } else if (!behind_box(light, q, 0.6f)) {
        ++lit;
        lit_dark += value < 0.9f;
      }
    }
    std::printf("light %d: umbra %d/%d dark, open ground %d/%d dark\n", i, umbra_dark, umbra,
                lit_dark, lit);
    EXPECT_GT(umbra, 20) << "light " << i;
    EXPECT_EQ(umbra_dark, umbra) << "light " << i;
    EXPECT_LE(lit_dark, lit / 1000) << "light " << i;
  }
}

std::vector<Combination> combinations() {
  std::vector<Combination> all;
  for (LightType light : {LightType::Point, LightType::Directional}) {
    for (Technique t : {Technique::None, Technique::Hard, Technique::Pcf, Technique::Pcss}) {
      all.push_back({light, t, Filter::Gaussian, false});
    }
    for (Technique t : {Technique::Vsm, Technique::Esm, Technique::Msm, Technique::Msm16}) {
      all.push_back({light, t, Filter::Gaussian, false});
      if (t == Technique::Esm) continue;  // esm cannot use the summed-area table
      all.push_back({light, t, Filter::Sat, false});
      all.push_back({light, t, Filter::Sat, true});
    }
  }
  return all;
}

std::string name_of(const ::testing::TestParamInfo<Combination>& info) {
  const Combination& c = info.param;
  std::ostringstream name;
  name << enum_name<LightType>(kLightTypeNames, c.light) << '_'
       << enum_name<Technique>(kTechniqueNames, c.technique);
  if (is_filterable(c.technique)) name << '_' << enum_name<Filter>(kFilterNames, c.filter);
  if (c.soft) name << "_soft";
  return name.str();
}

INSTANTIATE_TEST_SUITE_P(EveryTechnique, LightTypeTest, ::testing::ValuesIn(combinations()),
                         name_of);

}  // namespace
}  // namespace penumbra
