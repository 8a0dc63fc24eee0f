#pragma once
// Renders the relative depth z-bar of every shadow view (the views of all
// lights: see shadow/shadow_views.hpp) into the layers of one depth-texture
// array.
#include <vector>

#include "gl/program.hpp"
#include "gl/resources.hpp"
#include "render/gpu_scene.hpp"

namespace penumbra {

class ShadowMapPass {
 public:
  // The depth maps' format.
  static constexpr GLenum kDepthFormat = GL_DEPTH_COMPONENT32F;

  ShadowMapPass();

  // Draws the scene from views 0..view_count-1 of the shadow-views block
  // (which must be bound), view i into layer i. The array is reallocated
  // only when the view count or the size changes.
  void execute(const GpuScene& scene, int view_count, int map_size);

  // DEPTH_COMPONENT32F 2D array holding z-bar, one layer per view. Valid
  // after execute().
  [[nodiscard]] const gl::Texture& depth_maps() const { return maps_; }

 private:
  gl::Program program_;          // opaque surfaces
  gl::Program cut_out_program_;  // alpha-tested and single-sided ones
  gl::Texture maps_;
  std::vector<gl::Framebuffer> framebuffers_;  // one per layer
};

}  // namespace penumbra
