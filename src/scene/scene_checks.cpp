#include "scene/scene_checks.hpp"

namespace penumbra {

CameraDefect camera_defect(const Camera& camera) {
  const glm::vec3 view = camera.target - camera.position;
  if (!is_usable_direction(view)) return CameraDefect::TargetAtPosition;
  // The view matrix builds its right axis from cross(view, up): a parallel
  // up leaves it zero (and the image blank).
  if (glm::length(glm::cross(camera.up, view)) < kMinSceneLength) return CameraDefect::UpAlongView;
  return CameraDefect::None;
}

bool is_usable_direction(const glm::vec3& direction) {
  return glm::length(direction) >= kMinSceneLength;
}

}  // namespace penumbra
