#include "penumbra/gl/gpu_profiler.hpp"

#include "penumbra/error.hpp"

namespace penumbra::gl {

GpuProfiler::GpuProfiler(int frames_in_flight, bool serialize)
    : frames_(static_cast<std::size_t>(frames_in_flight)), serialize_(serialize) {
  for (Frame& f : frames_) {
    f.queries.resize(kQueriesPerFrame);
    f.wall_ms.resize(kQueriesPerFrame);
    glCreateQueries(GL_TIMESTAMP, kQueriesPerFrame, f.queries.data());
  }
}

GpuProfiler::~GpuProfiler() {
  for (Frame& f : frames_) glDeleteQueries(kQueriesPerFrame, f.queries.data());
}

int GpuProfiler::record(GpuPass) {
  Frame& f = frames_[static_cast<std::size_t>(current_)];
  if (f.used >= kQueriesPerFrame) throw RuntimeError("GPU profiler: too many passes in a frame");
  if (serialize_) {
    glFinish();
    f.wall_ms[static_cast<std::size_t>(f.used)] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - epoch_)
            .count();
  }
  glQueryCounter(f.queries[static_cast<std::size_t>(f.used)], GL_TIMESTAMP);
  return f.used++;
}

void GpuProfiler::begin_frame() {
  Frame& f = frames_[static_cast<std::size_t>(current_)];
  if (f.pending) {
    // The ring is full: the oldest frame's results are dropped unread.
    f.pending = false;
    oldest_ = (oldest_ + 1) % static_cast<int>(frames_.size());
  }
  f.used = 0;
  f.spans.clear();
  record(GpuPass::Count);  // the frame's start
}

void GpuProfiler::begin(GpuPass pass) {
  open_begin_ = record(pass);
}

void GpuProfiler::end(GpuPass pass) {
  const int end_index = record(pass);
  frames_[static_cast<std::size_t>(current_)].spans.push_back({pass, open_begin_, end_index});
}

void GpuProfiler::end_frame() {
  record(GpuPass::Count);  // the frame's end
  frames_[static_cast<std::size_t>(current_)].pending = true;
  current_ = (current_ + 1) % static_cast<int>(frames_.size());
}

std::optional<GpuFrameTimes> GpuProfiler::read(bool wait) {
  Frame& f = frames_[static_cast<std::size_t>(oldest_)];
  if (!f.pending) return std::nullopt;
  const GLuint last = f.queries[static_cast<std::size_t>(f.used - 1)];
  if (!wait) {
    GLint available = GL_FALSE;
    glGetQueryObjectiv(last, GL_QUERY_RESULT_AVAILABLE, &available);
    if (available != GL_TRUE) return std::nullopt;
  }
  std::vector<GLuint64> stamps(static_cast<std::size_t>(f.used));
  for (int i = 0; i < f.used; ++i) {
    glGetQueryObjectui64v(f.queries[static_cast<std::size_t>(i)], GL_QUERY_RESULT,
                          &stamps[static_cast<std::size_t>(i)]);
  }
  GpuFrameTimes times;
  for (const Frame::Span& span : f.spans) {
    const auto p = static_cast<std::size_t>(span.pass);
    times.pass_ms[p] += static_cast<double>(stamps[static_cast<std::size_t>(span.end)] -
                                            stamps[static_cast<std::size_t>(span.begin)]) *
                        1e-6;
    times.pass_wall_ms[p] += f.wall_ms[static_cast<std::size_t>(span.end)] -
                             f.wall_ms[static_cast<std::size_t>(span.begin)];
    times.ran[p] = true;
  }
  times.total_ms = static_cast<double>(stamps.back() - stamps.front()) * 1e-6;
  times.total_wall_ms = f.wall_ms[static_cast<std::size_t>(f.used - 1)] - f.wall_ms[0];
  f.pending = false;
  oldest_ = (oldest_ + 1) % static_cast<int>(frames_.size());
  return times;
}

}  // namespace penumbra::gl
