#pragma once
// The min/max depth hierarchy of a shadow-map array (Guennebaud, Barthe
// and Paulin, "High-Quality Adaptive Soft Shadow Mapping", Eurographics
// 2007; Schwarz and Stamminger, "Bitmask Soft Shadows", Eurographics
// 2007): level l holds, per cell of 2^(l + 1) x 2^(l + 1) texels, the
// nearest and farthest z-bar under it and the mean z-bar (GL_RGBA32F;
// shaders/filter/depth_hierarchy.comp). Built once per map after the
// depth pass; the backprojection lookup reads it for the region that can
// hold a receiver's blockers and for its coarse micro-patches.
#include <epoxy/gl.h>

#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/shadow/texel_traffic.hpp"

namespace penumbra {

class DepthHierarchyPass {
 public:
  // Fills every level of hierarchy() from every layer of `depth_maps`.
  void execute(const gl::Texture& depth_maps);

  // Valid after execute(): floor(size / 2) wide, down to 1 x 1.
  [[nodiscard]] const gl::Texture& hierarchy() const { return hierarchy_; }

  // Bytes per texel of a width x height depth map (depth_format) moved
  // by execute(): level 0 reads the map once, each level reads the one
  // below, and every level is written once (16 bytes a texel).
  static TexelTraffic texel_traffic(GLenum depth_format, int width, int height);

  // Frees the hierarchy (execute() makes it again), keeping the program.
  void release() { hierarchy_ = gl::Texture(); }

 private:
  gl::Program from_depth_ =
      gl::Program::compute("filter/depth_hierarchy.comp", {{"FROM_DEPTH", "1"}});
  gl::Program from_level_ =
      gl::Program::compute("filter/depth_hierarchy.comp", {{"FROM_DEPTH", "0"}});
  gl::Texture hierarchy_;
};

}  // namespace penumbra
