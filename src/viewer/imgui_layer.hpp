#pragma once
// Dear ImGui on a window: its context and its GLFW and OpenGL 3 backends.
// Create it after the window has installed its own input callbacks: the
// backend chains to them.
#include "viewer/window.hpp"

namespace penumbra {

class ImGuiLayer {
 public:
  explicit ImGuiLayer(Window& window);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  void begin_frame();
  // Draws what was built since begin_frame() into the window's framebuffer.
  void end_frame();

  // Whether the mouse or keyboard is the panel's this frame.
  [[nodiscard]] bool wants_mouse() const;
  [[nodiscard]] bool wants_keyboard() const;
};

}  // namespace penumbra
