#pragma once
// The mouse over the 3D view: left drag orbits the camera, right or middle
// drag pans it, the wheel zooms, and shift or ctrl + left drag moves the
// selected light (RenderSettings::light_index).
#include <glm/glm.hpp>
#include <optional>

#include "viewer/light_drag.hpp"
#include "viewer/orbit_camera.hpp"
#include "viewer/viewer_state.hpp"

namespace penumbra {

// One frame's mouse, in window pixels from the top-left corner.
struct MouseInput {
  glm::dvec2 cursor{0.0};
  bool left = false;
  bool right = false;
  bool middle = false;
  bool modifier = false;  // shift or ctrl held
  double scroll = 0.0;    // wheel steps since the last frame, up positive
};

class MouseControls {
 public:
  explicit MouseControls(const glm::vec3& scene_center) : scene_center_(scene_center) {}

  // `over_panel`: the panel wants the mouse; a drag that began over the
  // 3D view goes on over the panel.
  void update(const MouseInput& input, bool over_panel, int view_height, ViewerState& state,
              OrbitCamera& camera);

 private:
  enum class Drag { None, Orbit, Pan, Light };

  glm::vec3 scene_center_;
  Drag drag_ = Drag::None;
  glm::dvec2 last_cursor_{0.0};
  glm::dvec2 drag_start_{0.0};
  std::optional<LightDrag> light_drag_;
};

}  // namespace penumbra
