// Normals for meshes without them: smooth across gentle angles, creases
// kept, vertices found by position, and no blow-up at a fan's apex.
#include "scene/smooth_normals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace penumbra {
namespace {

// Unindexed triangles: one vertex per corner, as readers without sharing give.
TriangleMesh soup(const std::vector<glm::vec3>& corners) {
  TriangleMesh mesh;
  for (const glm::vec3& p : corners) {
    mesh.indices.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
    mesh.vertices.push_back({p, glm::vec3(0.0f), 0u});
  }
  return mesh;
}

void expect_unit_normals(const TriangleMesh& mesh) {
  for (const Vertex& v : mesh.vertices) {
    ASSERT_TRUE(std::isfinite(v.normal.x) && std::isfinite(v.normal.y) &&
                std::isfinite(v.normal.z));
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
  }
}

TEST(SmoothNormals, ABoxKeepsItsEdges) {
  // Two faces of a box meeting at 90 degrees along the edge x = 0..1, y = z = 0.
  const TriangleMesh mesh = with_smooth_normals(soup({{0, 0, 0},
                                                      {1, 0, 0},
                                                      {1, 0, -1},
                                                      {0, 0, 0},
                                                      {1, 0, -1},
                                                      {0, 0, -1},  // top, +y
                                                      {0, 0, 0},
                                                      {0, -1, 0},
                                                      {1, -1, 0},
                                                      {0, 0, 0},
                                                      {1, -1, 0},
                                                      {1, 0, 0}}),  // front, +z
                                                80.0f);
  ASSERT_EQ(mesh.indices.size(), 12u);
  expect_unit_normals(mesh);
  for (std::size_t c = 0; c < 12; ++c) {
    const glm::vec3 expected = c < 6 ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
    EXPECT_LT(glm::length(mesh.vertices[mesh.indices[c]].normal - expected), 1e-6f) << c;
  }
  // 4 + 4 positions, the two on the edge split in two.
  EXPECT_EQ(mesh.vertices.size(), 8u);
}

TEST(SmoothNormals, AGentleFoldIsSmoothAndShared) {
  // Two triangles at 27 degrees sharing an edge: the edge's corners get the
  // mean, so each position has one vertex.
  const float s = std::sin(glm::radians(20.0f)), c = std::cos(glm::radians(20.0f));
  const TriangleMesh mesh = with_smooth_normals(
      soup({{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {0, 0, 1}, {c, s, 1}}), 80.0f);
  expect_unit_normals(mesh);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  // On the shared edge: the area-weighted mean of the two faces' normals.
  const glm::vec3 expected = glm::normalize(glm::vec3(0, 1, 0) + glm::vec3(-s, c, -s));
  EXPECT_LT(glm::length(mesh.vertices[mesh.indices[1]].normal - expected), 1e-5f);
  EXPECT_LT(glm::length(mesh.vertices[mesh.indices[4]].normal - expected), 1e-5f);
}

TEST(SmoothNormals, ThousandsOfTrianglesAtOnePointStayLinear) {
  // A fan of 20000 triangles around one apex (a cone's tip).
  std::vector<glm::vec3> corners;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const float a0 = 2.0f * std::numbers::pi_v<float> * i / n;
    const float a1 = 2.0f * std::numbers::pi_v<float> * (i + 1) / n;
    corners.insert(corners.end(),
                   {{0, 1, 0}, {std::cos(a0), 0, -std::sin(a0)}, {std::cos(a1), 0, -std::sin(a1)}});
  }
  const TriangleMesh mesh = with_smooth_normals(soup(corners), 80.0f);
  expect_unit_normals(mesh);
  EXPECT_EQ(mesh.indices.size(), corners.size());
  // The apex takes the mean of all: straight up.
  EXPECT_NEAR(mesh.vertices[mesh.indices[0]].normal.y, 1.0f, 1e-4f);
}

TEST(SmoothNormals, DegenerateTrianglesGetUsableNormals) {
  const TriangleMesh mesh = with_smooth_normals(soup({{0, 0, 0},
                                                      {1, 0, 0},
                                                      {2, 0, 0},  // a line: no area
                                                      {5, 5, 5},
                                                      {5, 5, 5},
                                                      {5, 5, 5},  // a point
                                                      {0, 0, 0},
                                                      {1, 0, 0},
                                                      {0, 0, -1}}),  // a real one, sharing (0,0,0)
                                                80.0f);
  expect_unit_normals(mesh);
  EXPECT_NEAR(mesh.vertices[mesh.indices[0]].normal.y, 1.0f, 1e-6f) << "from its neighbour";
  EXPECT_NEAR(mesh.vertices[mesh.indices[3]].normal.y, 1.0f, 1e-6f) << "+y when nothing else";
}

}  // namespace
}  // namespace penumbra
