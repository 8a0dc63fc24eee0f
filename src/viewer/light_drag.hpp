#pragma once
// Moves a light with the mouse. A spot light circles the point it aims at
// (fixed when the drag starts) and keeps aiming there; a directional light
// turns its direction. Either moves the way the cursor does on screen:
// sideways about the vertical, up and down in elevation.
#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace penumbra {

class LightDrag {
 public:
  // `scene_center`: the spot light circles the point of its axis nearest it.
  LightDrag(const Light& light, const glm::vec3& scene_center);

  // The light after a drag of (dx, dy) pixels since begin (not since the
  // last call), seen by a camera whose right-hand direction is
  // `camera_right`.
  [[nodiscard]] Light dragged(float dx, float dy, const glm::vec3& camera_right) const;

  [[nodiscard]] const glm::vec3& pivot() const { return pivot_; }

 private:
  Light start_;
  glm::vec3 pivot_{0.0f};
};

}  // namespace penumbra
