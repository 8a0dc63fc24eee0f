#pragma once
// The mip chain of a filtered shadow-map array (--shadow-mips): levels
// 1..n-1, each the 2x2 mean of the level below (shaders/filter/
// downsample.comp), made after the filter so the lighting pass can read
// the map trilinearly and anisotropically over a pixel's footprint.
#include <epoxy/gl.h>

#include <map>

#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/shadow/texel_traffic.hpp"

namespace penumbra {

class MipChainPass {
 public:
  // Fills levels 1..maps.levels()-1 of every layer from level 0. The
  // texture's format must have an image format (representation_format()).
  void execute(const gl::Texture& maps);

  // Bytes per texel of level 0 of a width x height map with `levels`
  // levels: every level but the last is read once (the 2x2 texels each
  // coarser texel covers), every level but the first written once; about
  // 4/3 + 1/3 of the format's bytes.
  static TexelTraffic texel_traffic(GLenum format, int width, int height, int levels);

 private:
  std::map<GLenum, gl::Program> programs_;
};

}  // namespace penumbra
