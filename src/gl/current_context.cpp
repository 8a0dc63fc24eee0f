#include "penumbra/gl/current_context.hpp"

#include <dlfcn.h>

namespace penumbra::gl {

namespace {

// Calls `symbol` (eglGetCurrentContext or glXGetCurrentContext: no
// arguments, a context handle back) from `library` if the process has
// loaded it already; RTLD_NOLOAD never loads one. Not cached: a library
// may be loaded later, and destruction is rare.
bool library_reports_current(const char* library, const char* symbol) {
  void* handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD);
  if (handle == nullptr) return false;
  bool current = false;
  if (void* get = dlsym(handle, symbol)) {
    using GetCurrentContext = void* (*)();
    current = reinterpret_cast<GetCurrentContext>(get)() != nullptr;
  }
  dlclose(handle);
  return current;
}

}  // namespace

bool has_current_context() {
  // libglvnd's EGL and GLX front ends, and a GLX libGL without libglvnd.
  return library_reports_current("libEGL.so.1", "eglGetCurrentContext") ||
         library_reports_current("libGLX.so.0", "glXGetCurrentContext") ||
         library_reports_current("libGL.so.1", "glXGetCurrentContext");
}

}  // namespace penumbra::gl
