#pragma once
// A compute copy of a texture (shaders/filter/copy.comp): one read and one
// write per texel, the bandwidth yardstick the filter passes are measured
// against. Depth maps are copied into R32F (the same bytes per texel).
// Copies every layer of a 2D array.
#include <map>

#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/shadow/texel_traffic.hpp"

namespace penumbra {

class TextureCopyPass {
 public:
  void execute(const gl::Texture& source);
  // Per texel: one read of the source, one write of the copy.
  static TexelTraffic texel_traffic(GLenum source_format);
  [[nodiscard]] const gl::Texture& output() const { return output_; }

 private:
  std::map<GLenum, gl::Program> programs_;
  gl::Texture output_;
};

}  // namespace penumbra
