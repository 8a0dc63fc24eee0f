#include "viewer/orbit_camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace penumbra {

namespace {

// Short of the poles, where yaw loses its meaning and lookAt its up vector.
constexpr float kMaxPitch = glm::radians(89.0f);
constexpr float kMinDistance = 1e-3f;

}  // namespace

void OrbitCamera::set(const Camera& camera) {
  camera_ = camera;
  const glm::vec3 offset = camera.position - camera.target;
  distance_ = std::max(glm::length(offset), kMinDistance);
  pitch_ = std::asin(std::clamp(offset.y / distance_, -1.0f, 1.0f));
  yaw_ = std::atan2(offset.x, offset.z);
}

void OrbitCamera::update() {
  pitch_ = std::clamp(pitch_, -kMaxPitch, kMaxPitch);
  const float c = std::cos(pitch_);
  camera_.position = camera_.target + distance_ * glm::vec3(c * std::sin(yaw_), std::sin(pitch_),
                                                            c * std::cos(yaw_));
  camera_.up = {0.0f, 1.0f, 0.0f};
}

void OrbitCamera::orbit(float dx, float dy) {
  yaw_ -= dx * kRadiansPerPixel;
  pitch_ += dy * kRadiansPerPixel;
  update();
}

void OrbitCamera::pan(float dx, float dy, int viewport_height) {
  const glm::vec3 forward = glm::normalize(camera_.target - camera_.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 up = glm::cross(right, forward);
  // World units per pixel at the target's depth.
  const float scale = 2.0f * distance_ * std::tan(0.5f * glm::radians(camera_.fov_y_degrees)) /
                      static_cast<float>(std::max(viewport_height, 1));
  const glm::vec3 shift = (-dx * right + dy * up) * scale;
  camera_.target += shift;
  update();
}

void OrbitCamera::zoom(float steps) {
  distance_ = std::max(distance_ * std::pow(0.9f, steps), kMinDistance);
  update();
}

}  // namespace penumbra
