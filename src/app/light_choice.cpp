#include "app/light_choice.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "scene/mesh.hpp"

namespace penumbra {

void add_light_choice_option(CLI::App& app, std::string& choice) {
  app.add_option("--light", choice,
                 "light the scene with one light of this type alone: " +
                     enum_choices<LightType>(kLightTypeNames) +
                     " (the scene's own first light of that type, or one made from its first "
                     "light, aimed at the scene's centre; default: the scene's lights)");
}

Light single_light(const Scene& scene, LightType type) {
  for (const Light& light : scene.lights) {
    if (light.type == type) return light;
  }
  const Bounds bounds = build_scene_mesh(scene).bounds();
  const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  const float width = bounds.empty() ? 10.0f : glm::length(bounds.max - bounds.min);
  const Light& first = scene.lights.front();
  // Where a positional light goes, and the irradiance it gives the centre.
  glm::vec3 position = first.position;
  float irradiance = first.intensity;
  auto positional = std::find_if(scene.lights.begin(), scene.lights.end(),
                                 [](const Light& l) { return l.type != LightType::Directional; });
  if (positional != scene.lights.end()) {
    position = positional->position;
    irradiance =
        positional->intensity / std::max(glm::dot(position - center, position - center), 1e-6f);
  } else {
    position = center - width * glm::normalize(first.direction);
  }
  const float distance2 = std::max(glm::dot(position - center, position - center), 1e-6f);
  Light light = first;
  light.type = type;
  light.direction = glm::normalize(center - position);
  if (type == LightType::Directional) {
    light.intensity = irradiance;
  } else {
    light.position = position;
    light.intensity = irradiance * distance2;
  }
  if (type == LightType::Spot && first.type != LightType::Spot) {
    light.cone_degrees = 40.0f;
    light.inner_cone_degrees = 32.0f;
  }
  return light;
}

void apply_light_choice(const std::string& choice, Scene& scene) {
  if (choice.empty()) return;
  const std::optional<LightType> type = parse_enum<LightType>(kLightTypeNames, choice);
  if (!type) {
    throw UsageError("--light '" + choice + "': choose from " +
                     enum_choices<LightType>(kLightTypeNames));
  }
  if (scene.lights.empty()) {
    throw UsageError("--light " + choice + ": scene '" + scene.name +
                     "' has no light to start from");
  }
  scene.lights = {single_light(scene, *type)};
}

}  // namespace penumbra
