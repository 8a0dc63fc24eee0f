#pragma once
// Renders each light's relative depth z-bar into its own depth texture.
#include <vector>

#include "gl/program.hpp"
#include "gl/resources.hpp"
#include "render/gpu_scene.hpp"

namespace penumbra {

class ShadowMapPass {
 public:
  ShadowMapPass();

  // Draws the scene from lights 0..light_count-1 (the lights block must be
  // bound). Maps are reallocated only when the count or size changes.
  void execute(const GpuScene& scene, int light_count, int map_size);

  // Light i's map: DEPTH_COMPONENT32F holding z-bar. Valid after execute().
  [[nodiscard]] const gl::Texture& depth_map(int light) const { return maps_.at(light); }
  [[nodiscard]] int map_size() const { return size_; }
  [[nodiscard]] int map_count() const { return static_cast<int>(maps_.size()); }

 private:
  gl::Program program_;
  std::vector<gl::Texture> maps_;
  std::vector<gl::Framebuffer> framebuffers_;
  int size_ = 0;
};

}  // namespace penumbra
