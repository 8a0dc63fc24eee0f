#pragma once
// The driver's KHR_debug messages: errors are counted (tests and commands
// fail when the count grows, with one message naming the last); with
// `verbose`, each error and warning is printed as it comes.
// Shared by the headless context and the viewer's window.
#include <epoxy/gl.h>

#include <string>

namespace penumbra::gl {

class DebugOutput {
 public:
  explicit DebugOutput(bool verbose = false) : verbose_(verbose) {}
  DebugOutput(const DebugOutput&) = delete;
  DebugOutput& operator=(const DebugOutput&) = delete;

  // Routes the current context's messages here, synchronously (so an
  // error's message comes from the call that caused it). This object must
  // outlive the context.
  void install();

  [[nodiscard]] int error_count() const { return error_count_; }
  [[nodiscard]] const std::string& last_error() const { return last_error_; }

 private:
  static void GLAPIENTRY on_message(GLenum source, GLenum type, GLuint id, GLenum severity,
                                    GLsizei length, const GLchar* message, const void* user);

  bool verbose_ = false;
  int error_count_ = 0;
  std::string last_error_;
};

}  // namespace penumbra::gl
