#include "viewer/light_drag.hpp"

#include <algorithm>
#include <cmath>

#include "viewer/orbit_camera.hpp"

namespace penumbra {

namespace {

constexpr float kMaxElevation = glm::radians(89.0f);

// `offset` turned by `yaw` about +y and raised by `pitch` (clamped short
// of the poles), keeping its length.
glm::vec3 turned(const glm::vec3& offset, float yaw, float pitch) {
  const float r = glm::length(offset);
  if (r <= 0.0f) return offset;
  const float elevation = std::clamp(std::asin(std::clamp(offset.y / r, -1.0f, 1.0f)) + pitch,
                                     -kMaxElevation, kMaxElevation);
  const float azimuth = std::atan2(offset.x, offset.z) + yaw;
  const float c = std::cos(elevation);
  return r * glm::vec3(c * std::sin(azimuth), std::sin(elevation), c * std::cos(azimuth));
}

}  // namespace

LightDrag::LightDrag(const Light& light, const glm::vec3& scene_center) : start_(light) {
  if (light.type == LightType::Point) {  // no direction: it orbits the scene's centre
    pivot_ = scene_center;
    return;
  }
  const glm::vec3 axis = glm::normalize(light.direction);
  const float along = std::max(glm::dot(scene_center - light.position, axis), 1e-2f);
  pivot_ = light.position + along * axis;
}

Light LightDrag::dragged(float dx, float dy, const glm::vec3& camera_right) const {
  Light light = start_;
  // The offset from the pivot to the light (for a directional light, the
  // direction toward it), turned so that it follows the cursor.
  const glm::vec3 offset = light.type != LightType::Directional ? start_.position - pivot_
                                                                : -glm::normalize(start_.direction);
  // d(offset)/d(yaw) is (z, 0, -x): moving right on screen is the yaw whose
  // motion has a positive component along the camera's right.
  const glm::vec3 yaw_motion{offset.z, 0.0f, -offset.x};
  const float side = glm::dot(yaw_motion, camera_right) >= 0.0f ? 1.0f : -1.0f;
  const float k = OrbitCamera::kRadiansPerPixel;
  const glm::vec3 moved = turned(offset, side * dx * k, -dy * k);
  if (light.type != LightType::Directional) {
    light.position = pivot_ + moved;
    light.direction = glm::normalize(pivot_ - light.position);
  } else {
    light.direction = -glm::normalize(moved);
  }
  return light;
}

}  // namespace penumbra
