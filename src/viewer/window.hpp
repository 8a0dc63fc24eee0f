#pragma once
// A GLFW window with a current OpenGL 4.5 core context, its debug output,
// and the keys and mouse it received.
#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "penumbra/gl/debug_output.hpp"
#include "viewer/mouse_controls.hpp"

namespace penumbra {

struct WindowOptions {
  int width = 1280;  // in screen coordinates
  int height = 720;
  std::string title = "penumbra";
  bool vsync = true;
  bool verbose = false;  // print driver warnings too
};

struct KeyPress {
  int key = 0;   // GLFW_KEY_*
  int mods = 0;  // GLFW_MOD_*
};

class Window {
 public:
  // Whether a display server is named ($DISPLAY or $WAYLAND_DISPLAY).
  static bool display_named();

  // Opens the window (no larger than the primary monitor's work area) and
  // makes its context current. Throws RuntimeError
  // naming what failed (no display, no OpenGL 4.5 core context).
  explicit Window(const WindowOptions& options);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // Processes pending events; then keys() and mouse() hold what came since
  // the last call.
  void poll();
  // The same, but first waits up to `seconds` for an event (the idle loop).
  void wait(double seconds);
  [[nodiscard]] const std::vector<KeyPress>& keys() const { return keys_; }
  [[nodiscard]] MouseInput mouse() const;

  [[nodiscard]] bool should_close() const;
  void close();
  void swap_buffers();
  void set_clipboard(const std::string& text);

  [[nodiscard]] glm::ivec2 framebuffer_size() const;
  [[nodiscard]] glm::ivec2 window_size() const;
  [[nodiscard]] GLFWwindow* handle() const { return window_; }
  [[nodiscard]] const gl::DebugOutput& debug_output() const { return debug_; }

 private:
  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void on_scroll(GLFWwindow* window, double dx, double dy);
  void take_events();

  GLFWwindow* window_ = nullptr;
  gl::DebugOutput debug_;
  std::vector<KeyPress> keys_, pending_keys_;
  double scroll_ = 0.0, pending_scroll_ = 0.0;
};

}  // namespace penumbra
