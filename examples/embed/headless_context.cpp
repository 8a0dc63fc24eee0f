#include "headless_context.hpp"

#include <EGL/eglext.h>
#include <GL/glew.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace embed {

namespace {

// Whether `display`'s extension string (EGL_NO_DISPLAY: the client
// extensions) names `extension`.
bool has_extension(EGLDisplay display, std::string_view extension) {
  const char* list = eglQueryString(display, EGL_EXTENSIONS);
  if (list == nullptr) return false;
  const std::string_view all(list);
  for (std::size_t at = 0; at < all.size();) {
    const std::size_t end = std::min(all.find(' ', at), all.size());
    if (all.substr(at, end - at) == extension) return true;
    at = end + 1;
  }
  return false;
}

// An EGL extension function, or nullptr.
template <typename Function>
Function egl_function(const char* name) {
  return reinterpret_cast<Function>(eglGetProcAddress(name));
}

// A 4.5 core context without a surface on `display`, or EGL_NO_CONTEXT.
EGLContext create_context(EGLDisplay display) {
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
    return EGL_NO_CONTEXT;
  }
  if (!eglBindAPI(EGL_OPENGL_API) || !has_extension(display, "EGL_KHR_surfaceless_context") ||
      !has_extension(display, "EGL_KHR_no_config_context")) {
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               4,
                               EGL_CONTEXT_MINOR_VERSION,
                               5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT ||
      !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  }
  return context;
}

}  // namespace

HeadlessContext::HeadlessContext() {
  setenv("EGL_LOG_LEVEL", "fatal", 0);
  const auto get_platform_display =
      egl_function<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  const auto query_devices = egl_function<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  if (get_platform_display == nullptr) {
    throw std::runtime_error("EGL has no eglGetPlatformDisplayEXT");
  }
  if (query_devices != nullptr && has_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (query_devices(8, devices, &count)) {
      for (EGLint i = 0; i < count && context_ == EGL_NO_CONTEXT; ++i) {
        display_ = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        context_ = create_context(display_);
      }
    }
  }
  if (context_ == EGL_NO_CONTEXT &&
      has_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    context_ = create_context(display_);
  }
  if (context_ == EGL_NO_CONTEXT) {
    throw std::runtime_error("cannot create a headless OpenGL 4.5 core context through EGL");
  }
  // The engine's loader, with the context current. glewExperimental: the
  // core profile has no extension string for GLEW to read entry points by.
  // glewInit() loads the GL entry points, then GLX's: Debian's GLEW is
  // built for GLX, which a surfaceless EGL context has no display for
  // (GLEW_ERROR_NO_GLX_DISPLAY); the GL part is loaded all the same.
  glewExperimental = GL_TRUE;
  const GLenum loaded = glewInit();
  if ((loaded != GLEW_OK && loaded != GLEW_ERROR_NO_GLX_DISPLAY) || !GLEW_VERSION_4_5) {
    throw std::runtime_error(std::string("GLEW cannot load OpenGL 4.5: ") +
                             reinterpret_cast<const char*>(glewGetErrorString(loaded)));
  }
}

HeadlessContext::~HeadlessContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

}  // namespace embed
