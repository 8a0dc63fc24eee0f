// --light: the scene lit by one light of the chosen type.
#include "app/light_choice.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "penumbra/error.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/mesh.hpp"

namespace penumbra {
namespace {

TEST(LightChoice, KeepsTheScenesOwnLightOfThatType) {
  const Scene original = *builtin_scene("default");
  for (LightType type : {LightType::Spot, LightType::Directional}) {
    Scene scene = original;
    apply_light_choice(std::string(enum_name<LightType>(kLightTypeNames, type)), scene);
    ASSERT_EQ(scene.lights.size(), 1u);
    const auto own = std::find_if(original.lights.begin(), original.lights.end(),
                                  [&](const Light& l) { return l.type == type; });
    EXPECT_EQ(scene.lights[0].type, type);
    EXPECT_EQ(scene.lights[0].direction, own->direction);
    EXPECT_EQ(scene.lights[0].position, own->position);
  }
}

TEST(LightChoice, EveryTypeGivesTheCentreTheKeyLightsIrradiance) {
  // The default scene's spot light is its key light; its sun is a dim fill.
  const Scene original = *builtin_scene("default");
  const glm::vec3 center = build_scene_mesh(original).bounds().center();
  const Light& spot = original.lights[0];
  const glm::vec3 d = spot.position - center;
  const float key = spot.intensity / glm::dot(d, d);
  ASSERT_LT(original.lights[1].intensity, 0.5f * key);
  EXPECT_FLOAT_EQ(single_light(original, LightType::Spot).intensity, spot.intensity);
  EXPECT_NEAR(single_light(original, LightType::Directional).intensity, key, 1e-5f * key);
  const Light point = single_light(original, LightType::Point);
  const glm::vec3 dp = point.position - center;
  EXPECT_NEAR(point.intensity / glm::dot(dp, dp), key, 1e-5f * key);
}

TEST(LightChoice, APointLightTakesTheSpotLightsPlaceAndIntensity) {
  const Scene original = *builtin_scene("spot");
  Scene scene = original;
  apply_light_choice("point", scene);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, LightType::Point);
  EXPECT_EQ(scene.lights[0].position, original.lights[0].position);
  EXPECT_FLOAT_EQ(scene.lights[0].intensity, original.lights[0].intensity);
}

TEST(LightChoice, ASunKeepsTheIrradianceAtTheScenesCentre) {
  const Scene original = *builtin_scene("spot");
  const Light sun = single_light(original, LightType::Directional);
  EXPECT_EQ(sun.type, LightType::Directional);
  const glm::vec3 center = build_scene_mesh(original).bounds().center();
  const glm::vec3 d = original.lights[0].position - center;
  EXPECT_NEAR(sun.intensity, original.lights[0].intensity / glm::dot(d, d), 1e-5f);
  EXPECT_NEAR(glm::dot(sun.direction, -glm::normalize(d)), 1.0f, 1e-5f);
}

TEST(LightChoice, EmptyChoiceChangesNothingAndUnknownNamesAreErrors) {
  Scene scene = *builtin_scene("default");
  apply_light_choice("", scene);
  EXPECT_EQ(scene.lights.size(), 2u);
  EXPECT_THROW(apply_light_choice("lamp", scene), UsageError);
  scene.lights.clear();
  EXPECT_THROW(apply_light_choice("point", scene), UsageError);
}

}  // namespace
}  // namespace penumbra
