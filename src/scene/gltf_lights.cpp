#include "scene/gltf_lights.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra {

Light light_from_gltf(GltfLightType type, const glm::vec3& color, float intensity,
                      float inner_cone_radians, float outer_cone_radians) {
  Light light;
  light.type = type == GltfLightType::Directional ? LightType::Directional
               : type == GltfLightType::Spot      ? LightType::Spot
                                                  : LightType::Point;
  light.position = glm::vec3(0.0f);
  light.direction = {0.0f, 0.0f, -1.0f};
  const float scale = type == GltfLightType::Directional ? kIrradiancePerLux : kIntensityPerCandela;
  const glm::vec3 power = glm::max(color, glm::vec3(0.0f)) * std::max(intensity, 0.0f) * scale;
  const float largest = std::max({power.r, power.g, power.b});
  light.color = largest > 0.0f ? power / largest : glm::vec3(1.0f);
  light.intensity = largest;
  if (type == GltfLightType::Spot) {
    light.cone_degrees =
        std::clamp(glm::degrees(outer_cone_radians), kMinSpotConeDegrees, kMaxSpotConeDegrees);
    light.inner_cone_degrees =
        std::clamp(glm::degrees(inner_cone_radians), 0.0f, light.cone_degrees);
  }
  return light;
}

}  // namespace penumbra
