#pragma once
// A headless OpenGL 4.5 core context through EGL: the device platform first
// (NVIDIA and other GPUs without a display), then Mesa's surfaceless platform
// (llvmpipe on a machine without a GPU).
#include <epoxy/egl.h>

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "penumbra/gl/debug_output.hpp"

namespace penumbra::gl {

// Whether a GL_RENDERER string names a rasterizer that runs on the CPU
// (Mesa's llvmpipe and softpipe, SwiftShader).
bool is_cpu_rasterizer(std::string_view renderer);

struct ContextOptions {
  // Routes KHR_debug messages to the log; errors are always counted.
  bool debug = true;
  // Print debug messages of medium and high severity to stderr.
  bool verbose = false;
};

class Context {
 public:
  // Creates the context and makes it current on this thread. Throws
  // RuntimeError naming what is missing if no 4.5 core context can be had.
  static std::unique_ptr<Context> create_headless(const ContextOptions& options = {});
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Makes this context current on the calling thread (and whatever context
  // was current there no longer current). A context is current on one
  // thread at a time: make another current on the thread that held this
  // one before calling this on a second thread.
  void make_current();

  [[nodiscard]] std::string renderer() const;
  [[nodiscard]] std::string vendor() const;
  [[nodiscard]] std::string version() const;
  // "EGL device" or "Mesa surfaceless": how the context was obtained.
  [[nodiscard]] const std::string& platform() const { return platform_; }
  [[nodiscard]] int max_texture_size() const;

  // Number of GL_DEBUG_TYPE_ERROR messages seen since creation; tests fail
  // when it grows.
  [[nodiscard]] int error_count() const { return debug_ ? debug_->error_count() : 0; }
  [[nodiscard]] std::string last_error() const { return debug_ ? debug_->last_error() : ""; }

 private:
  Context() = default;

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;
  std::string platform_;
  std::unique_ptr<DebugOutput> debug_;
};

}  // namespace penumbra::gl
