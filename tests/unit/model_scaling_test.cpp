// A million-triangle model loads whole and correct. (How fast is printed,
// not asserted: timings belong to benchmarks, not tests.)
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "model_files.hpp"
#include "scene/mesh.hpp"
#include "scene/model.hpp"

namespace penumbra {
namespace {

TEST(ModelScaling, LoadsAMillionTriangleGrid) {
  constexpr int kQuads = 708;  // 2 * 708^2 = 1,002,528 triangles
  const std::string path = testing::write_grid_ply("grid-1m.ply", kQuads);
  const auto start = std::chrono::steady_clock::now();
  Scene scene;
  Shape shape;
  attach_model(scene, shape, path, /*own_materials=*/true);
  shape.scale = glm::vec3(4.0f);
  const TriangleMesh mesh = build_scene_mesh(Scene{
      .name = "grid", .materials = scene.materials, .shapes = {shape}, .camera = {}, .lights = {}});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("loaded and placed %zu triangles in %.2f s\n", mesh.indices.size() / 3, seconds);

  const std::size_t triangles = 2u * kQuads * kQuads;
  ASSERT_EQ(mesh.indices.size(), 3 * triangles);
  // The reader's per-corner vertices are joined back into the grid's.
  EXPECT_EQ(mesh.vertices.size(), static_cast<std::size_t>((kQuads + 1) * (kQuads + 1)));
  const Bounds b = mesh.bounds();
  EXPECT_EQ(b.min, glm::vec3(0.0f));
  EXPECT_NEAR(b.max.x, 4.0f, 1e-5f);
  EXPECT_EQ(b.max.y, 0.0f);
  EXPECT_NEAR(b.max.z, 4.0f, 1e-5f);
  std::size_t bad_indices = 0, bad_normals = 0, bad_winding = 0;
  for (std::uint32_t i : mesh.indices) bad_indices += i >= mesh.vertices.size();
  for (const Vertex& v : mesh.vertices) bad_normals += v.normal.y < 0.9999f;
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
    const glm::vec3 a = mesh.vertices[mesh.indices[i]].position;
    const glm::vec3 n = glm::cross(mesh.vertices[mesh.indices[i + 1]].position - a,
                                   mesh.vertices[mesh.indices[i + 2]].position - a);
    bad_winding += !(n.y > 0.0f);
  }
  EXPECT_EQ(bad_indices, 0u);
  EXPECT_EQ(bad_normals, 0u);
  EXPECT_EQ(bad_winding, 0u);
}

}  // namespace
}  // namespace penumbra
