#pragma once
// A camera that orbits, pans and zooms about its target, driven by mouse
// movements in pixels. The world's up is +y.
#include "scene/scene.hpp"

namespace penumbra {

class OrbitCamera {
 public:
  explicit OrbitCamera(const Camera& start) { set(start); }

  // Turns about the target: dragging right moves the camera to its left
  // (the scene turns with the cursor), dragging down raises it.
  void orbit(float dx, float dy);
  // Moves camera and target in the view plane, so the point under the
  // cursor at the target's depth follows the cursor.
  void pan(float dx, float dy, int viewport_height);
  // Moves toward the target (steps > 0) or away, 10 % per step.
  void zoom(float steps);

  // The camera as it is; exactly the one set until the first movement.
  [[nodiscard]] const Camera& camera() const { return camera_; }
  // Follows a camera changed elsewhere (the panel, a reset).
  void set(const Camera& camera);

  static constexpr float kRadiansPerPixel = 0.005f;

 private:
  void update();

  Camera camera_;
  float yaw_ = 0.0f;    // about +y, 0 looking from +z
  float pitch_ = 0.0f;  // elevation above the target
  float distance_ = 1.0f;
};

}  // namespace penumbra
