#include "penumbra/gl/context.hpp"

#include <epoxy/gl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "penumbra/error.hpp"

namespace penumbra::gl {

namespace {

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

struct Attempt {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;
};

// Initializes `display` and creates a current 4.5 core context on it.
// Returns an empty string on success, or why it failed.
std::string try_display(EGLDisplay display, bool debug, Attempt& out) {
  if (display == EGL_NO_DISPLAY) return "no display";
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    return eglGetError() == EGL_BAD_ALLOC ? "eglInitialize failed: out of memory"
                                          : "eglInitialize failed";
  }
  auto fail = [&](const std::string& why) {
    eglTerminate(display);
    return why;
  };
  if (!eglBindAPI(EGL_OPENGL_API)) return fail("desktop OpenGL API not available");
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);

  EGLConfig config = EGL_NO_CONFIG_KHR;
  const bool no_config = has_extension(extensions, "EGL_KHR_no_config_context");
  const bool surfaceless = has_extension(extensions, "EGL_KHR_surfaceless_context");
  if (!no_config || !surfaceless) {
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                     EGL_OPENGL_BIT, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(display, config_attribs, &config, 1, &count) || count < 1) {
      return fail("no EGL config for desktop OpenGL");
    }
  }
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                    4,
                                    EGL_CONTEXT_MINOR_VERSION,
                                    5,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_CONTEXT_OPENGL_DEBUG,
                                    debug ? EGL_TRUE : EGL_FALSE,
                                    EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
  if (context == EGL_NO_CONTEXT) return fail("no OpenGL 4.5 core context");
  EGLSurface surface = EGL_NO_SURFACE;
  if (!surfaceless) {
    const EGLint pbuffer_attribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface = eglCreatePbufferSurface(display, config, pbuffer_attribs);
  }
  if (!eglMakeCurrent(display, surface, surface, context)) {
    eglDestroyContext(display, context);
    return fail("eglMakeCurrent failed");
  }
  out = {display, context, surface};
  return {};
}

}  // namespace

bool is_cpu_rasterizer(std::string_view renderer) {
  for (const char* software : {"llvmpipe", "softpipe", "SwiftShader"}) {
    if (renderer.find(software) != std::string_view::npos) return true;
  }
  return false;
}

namespace {

// Mesa keeps compiled shaders in $XDG_CACHE_HOME/mesa_shader_cache (or
// ~/.cache/...) and, where it cannot make that folder (a read-only or
// missing HOME), prints "Failed to create ... for shader cache
// ---disabling." on stderr. Found here first, the cache is turned off
// quietly instead. Values the user set are kept.
void disable_unusable_shader_cache() {
  if (std::getenv("MESA_SHADER_CACHE_DISABLE") != nullptr ||
      std::getenv("MESA_SHADER_CACHE_DIR") != nullptr) {
    return;
  }
  std::string base;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    base = xdg;
  } else if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    base = std::string(home) + "/.cache";
  } else {
    return;  // Mesa asks the password database, and says nothing
  }
  std::error_code ec;
  std::filesystem::create_directories(base, ec);
  if (ec || access(base.c_str(), W_OK | X_OK) != 0) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
  }
}

}  // namespace

std::unique_ptr<Context> Context::create_headless(const ContextOptions& options) {
  // Mesa's libEGL prints warnings of its own (a device it cannot open, a
  // driver it cannot load) before a platform that works is found: only on
  // request. A value the user set is kept.
  if (!options.verbose) {
    setenv("EGL_LOG_LEVEL", "fatal", 0);
    disable_unusable_shader_cache();
  }
  std::unique_ptr<Context> ctx(new Context());
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  std::string tried;
  Attempt attempt;
  bool ok = false;

  if (has_extension(client_extensions, "EGL_EXT_platform_device") &&
      has_extension(client_extensions, "EGL_EXT_device_enumeration")) {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (eglQueryDevicesEXT(16, devices, &count)) {
      for (EGLint i = 0; i < count && !ok; ++i) {
        EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        std::string why = try_display(display, options.debug, attempt);
        ok = why.empty();
        if (!ok) tried += "EGL device " + std::to_string(i) + ": " + why + "; ";
      }
      if (count == 0) tried += "EGL device platform: no devices; ";
    }
    if (ok) ctx->platform_ = "EGL device";
  } else {
    tried += "EGL device platform: not supported; ";
  }
  if (!ok && has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    std::string why = try_display(display, options.debug, attempt);
    ok = why.empty();
    if (ok) ctx->platform_ = "Mesa surfaceless";
    if (!ok) tried += "Mesa surfaceless platform: " + why + "; ";
  } else if (!ok) {
    tried += "Mesa surfaceless platform: not supported; ";
  }
  if (!ok) {
    tried.resize(tried.size() - 2);
    // Under an address-space limit, drivers fail to load or initialize
    // (a dlopen or an allocation fails): that limit is the likely cause.
    // Otherwise advice on what to install, where something is missing.
    const bool missing = tried.find("eglInitialize failed") == std::string::npos;
    rlimit limit{};
    const bool limited = getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
    std::string advice;
    if (limited) {
      advice = "; the address space is limited (ulimit -v): too little for the driver?";
    } else if (missing) {
      advice = "; install Mesa's libegl-mesa0 and libgl1-mesa-dri, or a GPU driver with EGL";
    }
    throw RuntimeError("cannot create a headless OpenGL 4.5 core context (" + tried + ")" + advice);
  }
  ctx->display_ = attempt.display;
  ctx->context_ = attempt.context;
  ctx->surface_ = attempt.surface;
  if (epoxy_gl_version() < 45) {
    throw RuntimeError("the OpenGL context is version " + ctx->version() + ", 4.5 is required");
  }
  if (options.debug) {
    ctx->debug_ = std::make_unique<DebugOutput>(options.verbose);
    ctx->debug_->install();
  }
  return ctx;
}

Context::~Context() {
  if (display_ != EGL_NO_DISPLAY) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    // The display is shared by every context on it in this process; EGL
    // reference-counts nothing, so terminating here would break the others.
  }
}

void Context::make_current() {
  if (!eglMakeCurrent(display_, surface_, surface_, context_)) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
    throw RuntimeError(std::string("eglMakeCurrent failed (EGL error ") + code + ")");
  }
}

std::string Context::renderer() const {
  return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}
std::string Context::vendor() const {
  return reinterpret_cast<const char*>(glGetString(GL_VENDOR));
}
std::string Context::version() const {
  return reinterpret_cast<const char*>(glGetString(GL_VERSION));
}
int Context::max_texture_size() const {
  GLint size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  return size;
}

}  // namespace penumbra::gl
