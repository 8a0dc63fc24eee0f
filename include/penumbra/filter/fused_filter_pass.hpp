#pragma once
// Resolve + separable Gaussian in one compute pass (Peters et al., HPG 2017):
// the z-bar depth-map array -> the technique's filtered representation,
// written once (shaders/filter/fused_filter.comp). The same result as
// MomentResolvePass followed by GaussianBlurPass, up to the rounding of
// their intermediate maps, for radii 1..kMaxFusedBlur; the renderer picks
// it with uses_fused_filter(). On a CPU rasterizer it filters without
// shared memory, in two dispatches per band of 256 rows through a float
// map of the band (FilterStaging::Direct): the same floats.
#include <epoxy/gl.h>

#include <cstdint>
#include <map>
#include <span>
#include <tuple>

#include "penumbra/filter/filter_staging.hpp"
#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/texel_traffic.hpp"

namespace penumbra {

class FusedFilterPass {
 public:
  explicit FusedFilterPass(FilterStaging staging = FilterStaging::Automatic);

  // Filters every layer of `depth_maps` with the settings' technique and
  // radius (settings.blur in 1..max_fused_blur()) into output(); a
  // multisampled array (ShadowMapPass::sampled_depth_maps()) has the mean
  // of each texel's samples' representations filtered; or, given `layers`
  // (a flag per layer), only the flagged ones, the others kept (all of them
  // when output() is allocated anew).
  void execute(const gl::Texture& depth_maps, const ShadowMapSettings& settings,
               std::span<const std::uint8_t> layers = {});

  // Same size, layers and format as the resolve's representation. Valid
  // after execute().
  [[nodiscard]] const gl::Texture& output() const { return output_; }

  // Rows of the tile each workgroup filters (32 wide) for a radius and a
  // representation of `channels` floats (`staged_floats` staged per texel:
  // staged_channels(), or evsm4's two warps): the tallest of 32, 16 and 8
  // whose shared memory fits `shared_bytes`; 0 if none does.
  static int tile_rows(int radius, int channels, int shared_bytes, int staged_floats = 1);

  // Floats staged per texel: one (the value the moments are expanded
  // from), or with `samples` > 1 the representation's channels (the mean
  // of the samples' moments).
  static int staged_channels(GLenum format, int samples);

  // Whether evsm4 stages its two warps per texel (computed once a texel
  // instead of once a tap): where they fit in a tile as tall as the one
  // float staged would give, so the tile and its traffic stay the same.
  static bool stages_evsm4_warps(int radius, int shared_bytes);

  // Bytes per texel of a width x height map, staged in shared memory (a
  // GPU's path; FilterStaging::Direct reads each tap and writes and reads
  // the rows too): each 32 x tile_rows() tile
  // reads the depth (R32F, `samples` per texel) under it and its apron of
  // `radius` on every side, and writes the representation (`format`) once.
  static TexelTraffic texel_traffic(GLenum format, int radius, int width, int height,
                                    int shared_bytes, int samples = 1);

  // Frees the output and the direct staging's rows (execute() makes them
  // again), keeping the programs.
  void release() {
    output_ = gl::Texture();
    rows_ = gl::Texture();
  }

 private:
  // (technique, quantized, radius, tile rows, samples per depth texel,
  // pass: 0 the shared-memory tile, 1 and 2 the direct staging's)
  using ProgramKey = std::tuple<Technique, bool, int, int, int, int>;
  const gl::Program& program(const ProgramKey& key);

  std::map<ProgramKey, gl::Program> programs_;
  bool shared_memory_ = true;
  int shared_bytes_ = 0;  // GL_MAX_COMPUTE_SHARED_MEMORY_SIZE
  gl::Texture output_;
  gl::Texture rows_;  // the direct staging's: step 2's rows of one band and its apron, in floats
};

}  // namespace penumbra
