#pragma once
// A scene's triangles and materials on the GPU, drawn with one call.
#include "gl/resources.hpp"
#include "scene/mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// Mirrors the Material struct of shaders/scene/material.glsl (std430).
struct GpuMaterial {
  glm::vec4 albedo;
  glm::vec4 specular_shininess;
};
static_assert(sizeof(GpuMaterial) == 32);

class GpuScene {
 public:
  GpuScene(const Scene& scene, const TriangleMesh& mesh);

  // Binds the vertex array and the materials, and draws every triangle.
  void draw() const;
  [[nodiscard]] std::size_t triangle_count() const { return index_count_ / 3; }

 private:
  gl::Buffer vertices_;
  gl::Buffer indices_;
  gl::Buffer materials_;
  gl::VertexArray vao_;
  std::size_t index_count_ = 0;
};

}  // namespace penumbra
