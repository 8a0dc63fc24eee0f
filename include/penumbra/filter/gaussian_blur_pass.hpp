#pragma once
// Separable Gaussian blur in compute: horizontal into an intermediate
// texture, then vertical into the output, each pass staging its tile in
// shared memory (shaders/filter/gaussian_blur.comp). Works on 2D array
// textures: each layer (one shadow view) is filtered on its own.
#include <cstdint>
#include <map>
#include <span>
#include <tuple>

#include "penumbra/filter/filter_staging.hpp"
#include "penumbra/gl/gpu_profiler.hpp"
#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/shadow/texel_traffic.hpp"

namespace penumbra {

class GaussianBlurPass {
 public:
  // How each workgroup reads its taps (shaders/filter/gaussian_blur.comp).
  using Staging = FilterStaging;
  explicit GaussianBlurPass(Staging staging = Staging::Automatic);

  // Blurs every layer of the 2D array `source` with 2 radius + 1 taps per
  // direction into output() (same size, layers and format). radius >= 1.
  // `levels`: mip levels of output() (MipChainPass fills levels 1..; this
  // pass writes level 0). `layers`: a flag per layer to blur only those
  // (FusedFilterPass).
  void execute(const gl::Texture& source, int radius, gl::GpuProfiler* profiler = nullptr,
               int levels = 1, std::span<const std::uint8_t> layers = {});

  // Valid after execute().
  [[nodiscard]] const gl::Texture& output() const { return output_; }

  // Per texel of a width x height map of `format`, one direction (axis 0:
  // along x): each workgroup reads its tile (shared/filter_tiles.h; the
  // tiles that overhang the map read clamped border texels) with `radius`
  // texels of apron on either side along the axis, and writes the tile's
  // texels inside the map: about 1 + 2 radius / GAUSSIAN_TILE_ALONG reads
  // and one write.
  static TexelTraffic texel_traffic(GLenum format, int radius, int axis, int width, int height);

  // Frees the output and the intermediate (execute() makes them again),
  // keeping the programs.
  void release() {
    intermediate_ = gl::Texture();
    output_ = gl::Texture();
  }

 private:
  const gl::Program& program(GLenum format, int axis, int radius);
  void dispatch(const gl::Program& program, const gl::Texture& from, const gl::Texture& to,
                int axis, std::span<const std::uint8_t> layers, bool all);

  std::map<std::tuple<GLenum, int, int>, gl::Program> programs_;
  bool shared_memory_ = true;
  gl::Texture intermediate_;
  gl::Texture output_;
};

}  // namespace penumbra
