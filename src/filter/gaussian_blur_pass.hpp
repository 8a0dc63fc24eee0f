#pragma once
// Separable Gaussian blur in compute: horizontal into an intermediate
// texture, then vertical into the output, each pass staging its tile in
// shared memory (shaders/filter/gaussian_blur.comp).
#include <map>
#include <tuple>
#include <vector>

#include "gl/gpu_profiler.hpp"
#include "gl/program.hpp"
#include "gl/resources.hpp"

namespace penumbra {

class GaussianBlurPass {
 public:
  GaussianBlurPass();

  // Blurs `source` with 2 radius + 1 taps per direction into light
  // `light`'s output (same size and format as the source). radius >= 1.
  void execute(int light, const gl::Texture& source, int radius,
               gl::GpuProfiler* profiler = nullptr);

  // Valid after execute() for that light.
  [[nodiscard]] const gl::Texture& output(int light) const { return outputs_.at(light); }

 private:
  const gl::Program& program(GLenum format, int axis, int radius);
  void dispatch(const gl::Program& program, const gl::Texture& from, const gl::Texture& to,
                int axis);

  std::map<std::tuple<GLenum, int, int>, gl::Program> programs_;
  gl::Buffer weights_;
  int weights_radius_ = -1;
  gl::Texture intermediate_;  // shared by every light: they are blurred one after another
  std::vector<gl::Texture> outputs_;
};

}  // namespace penumbra
