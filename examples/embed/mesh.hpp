#pragma once
// The engine's own mesh: positions and normals in world space, a triangle
// list, on the GPU in one vertex array (position at attribute location 0,
// as penumbra's caster program reads it; normal at 1).
// The engine's own GL loader (GLEW); penumbra's headers bring none.
#include <GL/glew.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace embed {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
};

struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
};

// The ground plane and the box of scene.hpp.
Mesh make_scene_mesh();

class GpuMesh {
 public:
  explicit GpuMesh(const Mesh& mesh);
  ~GpuMesh();
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;
  void draw() const;

 private:
  GLuint vao_ = 0, vertices_ = 0, indices_ = 0;
  GLsizei index_count_ = 0;
};

}  // namespace embed
