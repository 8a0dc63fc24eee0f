#include "mesh.hpp"

#include <cstddef>

#include "scene.hpp"

namespace embed {

namespace {

// A quad with corners c, c + u, c + u + v, c + v, facing `normal`
// (counter-clockwise seen from outside).
void add_quad(Mesh& mesh, glm::vec3 c, glm::vec3 u, glm::vec3 v, glm::vec3 normal) {
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  for (glm::vec3 p : {c, c + u, c + u + v, c + v}) mesh.vertices.push_back({p, normal});
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + i);
}

}  // namespace

Mesh make_scene_mesh() {
  Mesh mesh;
  const float g = kGroundHalfSize;
  add_quad(mesh, {-g, 0.0f, g}, {2.0f * g, 0.0f, 0.0f}, {0.0f, 0.0f, -2.0f * g}, {0, 1, 0});
  const glm::vec3 lo = kBoxCenter - kBoxHalfSize, size = 2.0f * kBoxHalfSize;
  const glm::vec3 x{size.x, 0, 0}, y{0, size.y, 0}, z{0, 0, size.z};
  add_quad(mesh, lo + z, x, y, {0, 0, 1});       // front (+z)
  add_quad(mesh, lo + x, -x, y, {0, 0, -1});     // back: corner (hi.x, lo.y, lo.z)
  add_quad(mesh, lo + x + z, -z, y, {1, 0, 0});  // +x
  add_quad(mesh, lo, z, y, {-1, 0, 0});          // -x
  add_quad(mesh, lo + y + z, x, -z, {0, 1, 0});  // top
  add_quad(mesh, lo, x, z, {0, -1, 0});          // bottom
  return mesh;
}

GpuMesh::GpuMesh(const Mesh& mesh) : index_count_(static_cast<GLsizei>(mesh.indices.size())) {
  glCreateBuffers(1, &vertices_);
  glNamedBufferStorage(vertices_, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(Vertex)),
                       mesh.vertices.data(), 0);
  glCreateBuffers(1, &indices_);
  glNamedBufferStorage(indices_,
                       static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                       mesh.indices.data(), 0);
  glCreateVertexArrays(1, &vao_);
  glVertexArrayVertexBuffer(vao_, 0, vertices_, 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao_, indices_);
  glEnableVertexArrayAttrib(vao_, 0);
  glVertexArrayAttribFormat(vao_, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
  glVertexArrayAttribBinding(vao_, 0, 0);
  glEnableVertexArrayAttrib(vao_, 1);
  glVertexArrayAttribFormat(vao_, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, normal));
  glVertexArrayAttribBinding(vao_, 1, 0);
}

GpuMesh::~GpuMesh() {
  glDeleteVertexArrays(1, &vao_);
  glDeleteBuffers(1, &vertices_);
  glDeleteBuffers(1, &indices_);
}

void GpuMesh::draw() const {
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace embed
