#pragma once
// Separable Gaussian blur in compute: horizontal into an intermediate
// texture, then vertical into the output, each pass staging its tile in
// shared memory (shaders/filter/gaussian_blur.comp). Works on 2D array
// textures: each layer (one shadow view) is filtered on its own.
#include <map>
#include <tuple>

#include "gl/gpu_profiler.hpp"
#include "gl/program.hpp"
#include "gl/resources.hpp"

namespace penumbra {

class GaussianBlurPass {
 public:
  GaussianBlurPass();

  // Blurs every layer of the 2D array `source` with 2 radius + 1 taps per
  // direction into output() (same size, layers and format). radius >= 1.
  void execute(const gl::Texture& source, int radius, gl::GpuProfiler* profiler = nullptr);

  // Valid after execute().
  [[nodiscard]] const gl::Texture& output() const { return output_; }

 private:
  const gl::Program& program(GLenum format, int axis, int radius);
  void dispatch(const gl::Program& program, const gl::Texture& from, const gl::Texture& to,
                int axis);

  std::map<std::tuple<GLenum, int, int>, gl::Program> programs_;
  gl::Buffer weights_;
  int weights_radius_ = -1;
  gl::Texture intermediate_;
  gl::Texture output_;
};

}  // namespace penumbra
