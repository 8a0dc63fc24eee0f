#pragma once
// The map views of a light with several shadow views: its layers of a
// shadow-map array tiled into one 2D texture (shaders/render/tile_views.comp),
// three to a row: a point light's six cube faces in two rows (+x -x +y, -y
// +z -z), a directional light's cascades nearest first.
#include <epoxy/gl.h>

#include <map>

#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"

namespace penumbra {

class ViewTilingPass {
 public:
  // Tiles layers [first, first + count) of the 2D array `layers` into
  // output(), a float texture with the layers' channels (R32F for depth
  // maps); reallocated only when its size or format changes.
  // Throws UsageError if the tiled image exceeds the GPU's texture limit.
  void execute(const gl::Texture& layers, int first, int count);

  [[nodiscard]] const gl::Texture& output() const { return output_; }

  // Tiles per row for `count` views.
  static int columns(int count);

  // Frees the output (execute() makes it again).
  void release() { output_ = gl::Texture(); }

 private:
  const gl::Program& program(GLenum format);

  std::map<GLenum, gl::Program> programs_;  // per output format
  gl::Texture output_;
};

}  // namespace penumbra
