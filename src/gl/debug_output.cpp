#include "penumbra/gl/debug_output.hpp"

#include <cstdio>

namespace penumbra::gl {

void DebugOutput::install() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(&DebugOutput::on_message, this);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

void GLAPIENTRY DebugOutput::on_message(GLenum /*source*/, GLenum type, GLuint id, GLenum severity,
                                        GLsizei /*length*/, const GLchar* message,
                                        const void* user) {
  auto* self = static_cast<DebugOutput*>(const_cast<void*>(user));
  if (type == GL_DEBUG_TYPE_ERROR) {
    ++self->error_count_;
    self->last_error_ = message;
    // The command ends with one error line naming the last of them; each
    // is printed only on request.
    if (self->verbose_) std::fprintf(stderr, "penumbra: GL error %u: %s\n", id, message);
    return;
  }
  if (self->verbose_ && severity != GL_DEBUG_SEVERITY_NOTIFICATION) {
    std::fprintf(stderr, "penumbra: GL: %s\n", message);
  }
}

}  // namespace penumbra::gl
