#pragma once
// Resolve (compute): a light's z-bar depth map -> the technique's filterable
// representation (see representation.hpp).
#include <map>
#include <vector>

#include "core/settings.hpp"
#include "gl/program.hpp"
#include "gl/resources.hpp"

namespace penumbra {

class MomentResolvePass {
 public:
  // Writes light `light`'s representation. Textures are reallocated only
  // when the size or format changes.
  void execute(int light, const gl::Texture& depth_map, const ShadowSettings& settings);

  // Valid after execute() for that light.
  [[nodiscard]] const gl::Texture& representation(int light) const { return maps_.at(light); }

 private:
  std::map<std::pair<Technique, bool>, gl::Program> programs_;  // (technique, quantized)
  std::vector<gl::Texture> maps_;
};

}  // namespace penumbra
