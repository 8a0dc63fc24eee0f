#pragma once
// World-space triangle meshes built from a scene's shapes. The scene is
// static, so every shape is transformed once at build time and the whole
// scene draws with one call per pass (and the reference ray tracer sees the
// very same triangles).
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.hpp"

namespace penumbra {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  std::uint32_t material;
  glm::vec2 uv{0.0f};                 // texture coordinates, v up (see Material::uv_transform)
  std::uint32_t color = 0xffffffffu;  // linear RGBA, 8 bits each, red in the low byte
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

// The most vertex and index data a scene may have, in MiB: about 40
// million triangles, far above any scene or model this renders at
// interactive rates, and below what makes drivers fail (a scene of 70,000
// spheres, 160 million triangles, crashed Mesa's llvmpipe). The variable
// kGeometryBudgetVariable sets another budget in MiB.
inline constexpr std::size_t kDefaultGeometryBudgetMiB = 1024;
inline constexpr const char* kGeometryBudgetVariable = "PENUMBRA_GEOMETRY_BUDGET";

// The budget in bytes. Throws UsageError for a malformed variable.
std::size_t geometry_budget_bytes();

// Bytes of a mesh's vertices and indices, as uploaded.
std::size_t mesh_bytes(const TriangleMesh& mesh);

// All of a scene's shapes in one mesh. Throws UsageError naming the
// numbers when the mesh would exceed geometry_budget_bytes(). With
// `first_vertex`, also where each shape's vertices begin (one entry per
// shape, then the vertex count).
TriangleMesh build_scene_mesh(const Scene& scene, std::vector<std::size_t>* first_vertex = nullptr);

// The shape's model matrix: translate * rotate(z) * rotate(y) * rotate(x) * scale.
glm::mat4 shape_transform(const Shape& shape);

}  // namespace penumbra
