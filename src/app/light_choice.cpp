#include "app/light_choice.hpp"

#include <algorithm>
#include <cmath>

#include "app/option_style.hpp"
#include "core/display_name.hpp"
#include "penumbra/error.hpp"
#include "scene/mesh.hpp"

namespace penumbra {

void add_light_choice_option(CLI::App& app, std::string& choice) {
  std::vector<std::string> names;
  for (const auto& [type, name] : kLightTypeNames) names.emplace_back(name);
  add_choice(app, "light", choice,
             "light the scene with one light of this type alone: the scene's own first light "
             "of that type, or one made from its first light, aimed at the scene's centre; as "
             "bright there as the scene's key light (not given: the scene's lights)",
             names, OptionGroup::Lights);
}

namespace {

// Irradiance a light gives a point facing it, before its cone and shadows.
float irradiance_at(const Light& light, const glm::vec3& point) {
  if (light.type == LightType::Directional) return light.intensity;
  const glm::vec3 d = light.position - point;
  return light.intensity / std::max(glm::dot(d, d), 1e-6f);
}

}  // namespace

Light single_light(const Scene& scene, LightType type) {
  const Bounds bounds = build_scene_mesh(scene).bounds();
  const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  const float width = bounds.empty() ? 10.0f : glm::length(bounds.max - bounds.min);
  // The scene's key light: the one that gives its centre the most light.
  const Light& key = *std::max_element(scene.lights.begin(), scene.lights.end(),
                                       [&](const Light& a, const Light& b) {
                                         return irradiance_at(a, center) < irradiance_at(b, center);
                                       });
  const float irradiance = irradiance_at(key, center);

  Light light;
  auto own = std::find_if(scene.lights.begin(), scene.lights.end(),
                          [&](const Light& l) { return l.type == type; });
  if (own != scene.lights.end()) {
    light = *own;
  } else {
    // Where a positional light goes: where the scene's first one is, or,
    // with only suns, as far from the centre as the scene is wide, back
    // along the first light's direction.
    const Light& first = scene.lights.front();
    auto positional = std::find_if(scene.lights.begin(), scene.lights.end(),
                                   [](const Light& l) { return l.type != LightType::Directional; });
    const glm::vec3 position = positional != scene.lights.end()
                                   ? positional->position
                                   : center - width * glm::normalize(first.direction);
    light = first;
    light.type = type;
    light.position = position;
    light.direction = glm::normalize(center - position);
    if (type == LightType::Spot && first.type != LightType::Spot) {
      light.cone_degrees = 40.0f;
      light.inner_cone_degrees = 32.0f;
    }
  }
  // Alone, the light carries the key light's irradiance at the centre, so
  // the three types light the scene about equally (a scene's own sun is
  // often a dim fill light).
  light.intensity = light.type == LightType::Directional
                        ? irradiance
                        : irradiance * glm::dot(light.position - center, light.position - center);
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

void check_light_index(int light_index, const Scene& scene) {
  if (light_index >= static_cast<int>(scene.lights.size())) {
    throw UsageError("--light-index " + std::to_string(light_index) + ": scene " +
                     display_name(scene.name) + " has " + std::to_string(scene.lights.size()) +
                     " light(s)");
  }
}

}  // namespace penumbra
