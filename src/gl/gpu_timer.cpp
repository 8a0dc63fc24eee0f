#include "gl/gpu_timer.hpp"

namespace penumbra::gl {

GpuTimer::GpuTimer() {
  GLuint id = 0;
  glCreateQueries(GL_TIME_ELAPSED, 1, &id);
  query_ = Handle<detail::delete_query>(id);
}

void GpuTimer::begin() {
  glBeginQuery(GL_TIME_ELAPSED, query_.id());
}

void GpuTimer::end() {
  glEndQuery(GL_TIME_ELAPSED);
  ran_ = true;
}

std::optional<double> GpuTimer::milliseconds(bool wait) const {
  if (!ran_) return std::nullopt;
  GLint available = GL_FALSE;
  if (!wait) {
    glGetQueryObjectiv(query_.id(), GL_QUERY_RESULT_AVAILABLE, &available);
    if (available != GL_TRUE) return std::nullopt;
  }
  GLuint64 ns = 0;
  glGetQueryObjectui64v(query_.id(), GL_QUERY_RESULT, &ns);
  return static_cast<double>(ns) * 1e-6;
}

}  // namespace penumbra::gl
