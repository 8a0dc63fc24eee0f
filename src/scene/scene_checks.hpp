#pragma once
// What makes a camera or a light direction usable, checked the same way
// wherever one comes from: a scene file (scene_file.cpp) or the command
// line (--camera-position, --camera-target, --light-direction).
#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace penumbra {

// Shorter vectors cannot be normalized reliably in float (a direction of
// 1e-25 squares to 0): a camera closer to its target, or a direction
// shorter, is refused.
inline constexpr float kMinSceneLength = 1e-6f;

enum class CameraDefect {
  None,
  TargetAtPosition,  // the target is (within kMinSceneLength of) the position
  UpAlongView,       // the up vector is parallel to the viewing direction
};

[[nodiscard]] CameraDefect camera_defect(const Camera& camera);

// Whether `direction` is long enough to normalize.
[[nodiscard]] bool is_usable_direction(const glm::vec3& direction);

}  // namespace penumbra
