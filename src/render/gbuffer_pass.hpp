#pragma once
// The G-buffer: depth, normal + shininess, albedo, specular colour, and
// for the shadow lookups the triangle's normal and the rise to the smooth
// surface of the vertex normals (shaders/scene/smooth_surface.glsl).
#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "render/gpu_scene.hpp"

namespace penumbra {

class GBufferPass {
 public:
  GBufferPass();

  // Draws the scene from the camera (the frame block must be bound).
  // Targets are reallocated only when the size changes.
  void execute(const GpuScene& scene, int width, int height);

  [[nodiscard]] const gl::Texture& depth() const { return depth_; }
  [[nodiscard]] const gl::Texture& normal() const { return normal_; }
  [[nodiscard]] const gl::Texture& albedo() const { return albedo_; }
  [[nodiscard]] const gl::Texture& specular() const { return specular_; }
  [[nodiscard]] const gl::Texture& facet() const { return facet_; }

 private:
  gl::Program program_;          // opaque surfaces
  gl::Program cut_out_program_;  // alpha-tested and single-sided ones
  gl::Texture depth_, normal_, albedo_, specular_, facet_;
  gl::Framebuffer framebuffer_;
  int width_ = 0, height_ = 0;
};

}  // namespace penumbra
