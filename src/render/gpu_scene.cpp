#include "render/gpu_scene.hpp"

#include <cstddef>
#include <vector>

#include "shared/bindings.h"

namespace penumbra {

GpuScene::GpuScene(const Scene& scene, const TriangleMesh& mesh)
    : vertices_(gl::Buffer::from(std::span<const Vertex>(mesh.vertices), "scene vertices")),
      indices_(gl::Buffer::from(std::span<const std::uint32_t>(mesh.indices), "scene indices")),
      vao_("scene"),
      index_count_(mesh.indices.size()) {
  std::vector<GpuMaterial> materials;
  for (const Material& m : scene.materials) {
    materials.push_back({glm::vec4(m.albedo, 1.0f), glm::vec4(m.specular, m.shininess)});
  }
  if (materials.empty())
    materials.push_back({glm::vec4(0.8f), glm::vec4(0.04f, 0.04f, 0.04f, 32.0f)});
  materials_ = gl::Buffer::from(std::span<const GpuMaterial>(materials), "materials");

  const GLuint vao = vao_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, indices_.id());
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
  glVertexArrayAttribBinding(vao, 0, 0);
  glEnableVertexArrayAttrib(vao, 1);
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, normal));
  glVertexArrayAttribBinding(vao, 1, 0);
  glEnableVertexArrayAttrib(vao, 2);
  glVertexArrayAttribIFormat(vao, 2, 1, GL_UNSIGNED_INT, offsetof(Vertex, material));
  glVertexArrayAttribBinding(vao, 2, 0);
}

void GpuScene::draw() const {
  glBindVertexArray(vao_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_MATERIALS_SSBO, materials_.id());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(index_count_), GL_UNSIGNED_INT, nullptr);
}

}  // namespace penumbra
