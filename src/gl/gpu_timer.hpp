#pragma once
// GPU time of a span of commands, from a GL_TIME_ELAPSED query. The result
// is read when asked for, so a frame loop can read last frame's timers
// without stalling.
#include <epoxy/gl.h>

#include <optional>

#include "penumbra/gl/handle.hpp"

namespace penumbra::gl {

namespace detail {
inline void delete_query(GLuint id) {
  glDeleteQueries(1, &id);
}
}  // namespace detail

class GpuTimer {
 public:
  GpuTimer();
  void begin();
  void end();
  // Milliseconds, or nullopt if the result is not available yet (or the
  // timer never ran). With wait = true it blocks until the GPU is done.
  [[nodiscard]] std::optional<double> milliseconds(bool wait) const;

 private:
  Handle<detail::delete_query> query_;
  bool ran_ = false;
};

}  // namespace penumbra::gl
