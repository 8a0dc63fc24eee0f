#pragma once
// Resolve (compute): the z-bar depth-map array -> the technique's filterable
// representation (see representation.hpp), every layer (shadow view) at once.
#include <cstdint>
#include <map>
#include <span>
#include <tuple>

#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/texel_traffic.hpp"

namespace penumbra {

class MomentResolvePass {
 public:
  // Writes the representation of every layer of `depth_maps`: with more
  // than one sample per texel (ShadowMapPass::sampled_depth_maps()), the
  // mean of its samples' representations. The array is reallocated only
  // when its size, layer count or format changes.
  // `layers`: a flag per layer to resolve only those (FusedFilterPass).
  void execute(const gl::Texture& depth_maps, const ShadowMapSettings& settings,
               std::span<const std::uint8_t> layers = {});

  // Per texel: one depth read (of `depth_format`) per sample, one texel of
  // the technique's representation written.
  static TexelTraffic texel_traffic(GLenum depth_format, Technique technique, int samples = 1);

  // A 2D array like the depth maps. Valid after execute().
  [[nodiscard]] const gl::Texture& representation() const { return maps_; }

  // Frees the representation (execute() makes it again), keeping the
  // programs.
  void release() { maps_ = gl::Texture(); }

 private:
  // (technique, quantized, samples per depth texel)
  std::map<std::tuple<Technique, bool, int>, gl::Program> programs_;
  gl::Texture maps_;
};

}  // namespace penumbra
