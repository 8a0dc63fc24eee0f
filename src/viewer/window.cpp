#include "viewer/window.hpp"

#include <algorithm>
#include <cstdlib>

#include "penumbra/error.hpp"

namespace penumbra {

namespace {

std::string glfw_error() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description != nullptr ? description : "unknown GLFW error";
}

bool named(const char* variable) {
  const char* value = std::getenv(variable);
  return value != nullptr && value[0] != '\0';
}

}  // namespace

bool Window::display_named() {
  return named("DISPLAY") || named("WAYLAND_DISPLAY");
}

Window::Window(const WindowOptions& options) : debug_(options.verbose) {
  if (!display_named()) {
    throw RuntimeError(
        "no display: 'view' opens a window, and neither $DISPLAY nor $WAYLAND_DISPLAY is set "
        "(use 'render' for images without one)");
  }
  // Mesa's libEGL warnings (a driver it cannot load) only on request, as
  // for the headless context.
  if (!options.verbose) setenv("EGL_LOG_LEVEL", "fatal", 0);
  if (!glfwInit()) throw RuntimeError("cannot open a window: " + glfw_error());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
  glfwWindowHint(GLFW_DEPTH_BITS, 0);
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  // No larger than the monitor's work area (a 1280 x 720 screen, with the
  // panel beside a 1280 x 720 view): the view takes what is left.
  int width = options.width, height = options.height;
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
    int x = 0, y = 0, work_width = 0, work_height = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &work_width, &work_height);
    if (work_width > 0 && work_height > 0) {
      width = std::min(width, work_width);
      height = std::min(height, work_height);
    }
  }
  window_ = glfwCreateWindow(width, height, options.title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    const std::string why = glfw_error();
    glfwTerminate();
    throw RuntimeError("cannot open a window with an OpenGL 4.5 core context: " + why);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(options.vsync ? 1 : 0);
  glfwSetWindowUserPointer(window_, this);
  // Installed before the panel's, which chains to them.
  glfwSetKeyCallback(window_, &Window::on_key);
  glfwSetScrollCallback(window_, &Window::on_scroll);
  debug_.install();
}

Window::~Window() {
  if (window_ != nullptr) glfwDestroyWindow(window_);
  glfwTerminate();
}

void Window::on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (self != nullptr && (action == GLFW_PRESS || action == GLFW_REPEAT)) {
    self->pending_keys_.push_back({key, mods});
  }
}

void Window::on_scroll(GLFWwindow* window, double /*dx*/, double dy) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (self != nullptr) self->pending_scroll_ += dy;
}

void Window::poll() {
  glfwPollEvents();
  take_events();
}

void Window::wait(double seconds) {
  glfwWaitEventsTimeout(seconds);
  take_events();
}

void Window::take_events() {
  keys_.swap(pending_keys_);
  pending_keys_.clear();
  scroll_ = pending_scroll_;
  pending_scroll_ = 0.0;
}

MouseInput Window::mouse() const {
  MouseInput input;
  glfwGetCursorPos(window_, &input.cursor.x, &input.cursor.y);
  input.left = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  input.right = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  input.middle = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  input.modifier = glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                   glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS ||
                   glfwGetKey(window_, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                   glfwGetKey(window_, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
  input.scroll = scroll_;
  return input;
}

bool Window::should_close() const {
  return glfwWindowShouldClose(window_) != 0;
}

void Window::close() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void Window::swap_buffers() {
  glfwSwapBuffers(window_);
}

void Window::set_clipboard(const std::string& text) {
  glfwSetClipboardString(window_, text.c_str());
}

glm::ivec2 Window::framebuffer_size() const {
  glm::ivec2 size{0};
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

glm::ivec2 Window::window_size() const {
  glm::ivec2 size{0};
  glfwGetWindowSize(window_, &size.x, &size.y);
  return size;
}

}  // namespace penumbra
