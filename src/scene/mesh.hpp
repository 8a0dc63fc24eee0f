#pragma once
// World-space triangle meshes built from a scene's shapes. The scene is
// static, so every shape is transformed once at build time and the whole
// scene draws with one call per pass (and the reference ray tracer sees the
// very same triangles).
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.hpp"

namespace penumbra {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  std::uint32_t material;
};

struct TriangleMesh {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise from outside
  [[nodiscard]] Bounds bounds() const;
};

// Tessellation of curved shapes: segments around a full circle.
inline constexpr int kCurveSegments = 48;

// Appends one shape, transformed to world space. A model shape must have
// been loaded (scene/model.hpp: attach_model).
void append_shape(TriangleMesh& mesh, const Shape& shape);

// All of a scene's shapes in one mesh.
TriangleMesh build_scene_mesh(const Scene& scene);

// The shape's model matrix: translate * rotate(z) * rotate(y) * rotate(x) * scale.
glm::mat4 shape_transform(const Shape& shape);

}  // namespace penumbra
