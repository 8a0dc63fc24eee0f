#include "viewer/mouse_controls.hpp"

namespace penumbra {

void MouseControls::update(const MouseInput& input, bool over_panel, int view_height,
                           ViewerState& state, OrbitCamera& camera) {
  const Camera& shown = camera.camera();
  if (shown.position != state.camera.position || shown.target != state.camera.target ||
      shown.up != state.camera.up || shown.fov_y_degrees != state.camera.fov_y_degrees) {
    camera.set(state.camera);  // changed by the panel or a reset
  }
  const bool any_button = input.left || input.right || input.middle;
  if (!any_button) {
    drag_ = Drag::None;
    light_drag_.reset();
  } else if (drag_ == Drag::None && !over_panel) {
    drag_start_ = input.cursor;
    last_cursor_ = input.cursor;
    if (input.left && input.modifier && !state.lights.empty()) {
      drag_ = Drag::Light;
      const int index = state.render.light_index;
      light_drag_.emplace(state.lights.at(static_cast<std::size_t>(index)), scene_center_);
    } else {
      drag_ = input.left ? Drag::Orbit : Drag::Pan;
    }
  }
  const glm::vec2 delta(input.cursor - last_cursor_);
  last_cursor_ = input.cursor;

  const bool moved = delta != glm::vec2(0.0f);
  bool camera_moved = false;
  if (drag_ == Drag::Orbit && moved) {
    camera.orbit(delta.x, delta.y);
    camera_moved = true;
  } else if (drag_ == Drag::Pan && moved) {
    camera.pan(delta.x, delta.y, view_height);
    camera_moved = true;
  } else if (drag_ == Drag::Light && light_drag_ && moved) {
    const Camera& c = camera.camera();
    const glm::vec3 right = glm::cross(glm::normalize(c.target - c.position), c.up);
    const glm::vec2 total(input.cursor - drag_start_);
    set_light(state, state.render.light_index, light_drag_->dragged(total.x, total.y, right));
  }
  if (input.scroll != 0.0 && !over_panel) {
    camera.zoom(static_cast<float>(input.scroll));
    camera_moved = true;
  }
  if (camera_moved) set_camera(state, camera.camera());
}

}  // namespace penumbra
