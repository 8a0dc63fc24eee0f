#pragma once
// A headless OpenGL 4.5 core context through EGL: a GPU's EGL device if
// there is one, else Mesa's surfaceless platform (llvmpipe on a machine
// without a GPU). The engine owns its context; penumbra only uses it.
#include <EGL/egl.h>

#include <string>

namespace embed {

class HeadlessContext {
 public:
  // Makes the context current. Throws std::runtime_error saying what failed.
  HeadlessContext();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace embed
