// PositionSpan (include/penumbra/position_span.hpp): the casters' positions
// read in place from any vertex layout, so an engine's own vertex arrays
// fit the same shadow views as penumbra's scene meshes.
#include <gtest/gtest.h>

#include <penumbra/position_span.hpp>
#include <vector>

#include "penumbra/shadow/light_view.hpp"
#include "scene/mesh.hpp"

namespace penumbra {
namespace {

struct EngineVertex {
  float extra[5];  // something before the position
  glm::vec3 position;
  std::uint8_t more[3];
};

TEST(PositionSpan, ReadsPositionsOfAnyVertexLayout) {
  const std::vector<EngineVertex> vertices = {{{}, {1, 2, 3}, {}}, {{}, {4, 5, 6}, {}}};
  const PositionSpan span(vertices);
  ASSERT_EQ(span.size(), 2u);
  EXPECT_EQ(span[0], glm::vec3(1, 2, 3));
  EXPECT_EQ(span[1], glm::vec3(4, 5, 6));

  const std::vector<glm::vec3> plain = {{7, 8, 9}};
  EXPECT_EQ(PositionSpan(plain)[0], glm::vec3(7, 8, 9));
  const float interleaved[] = {1, 1, 1, 0, 2, 2, 2, 0};  // stride of four floats
  const PositionSpan strided(reinterpret_cast<const glm::vec3*>(interleaved), 2, 4 * sizeof(float));
  EXPECT_EQ(strided[1], glm::vec3(2, 2, 2));
  EXPECT_TRUE(PositionSpan(std::vector<EngineVertex>{}).empty());
}

TEST(PositionSpan, FitsTheSameViewFromEitherLayout) {
  TriangleMesh mesh;
  for (glm::vec3 p :
       {glm::vec3(-5, 0, -5), glm::vec3(5, 0, -5), glm::vec3(5, 0, 5), glm::vec3(0, 2, 0)}) {
    mesh.vertices.push_back({.position = p, .normal = {0, 1, 0}, .material = 0});
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  std::vector<glm::vec3> positions;
  for (const Vertex& v : mesh.vertices) positions.push_back(v.position);
  Light spot;
  spot.position = {1, 8, 1};
  const LightView a = fit_light_view(spot, mesh, 512);
  const LightView b = fit_light_view(spot, positions, mesh.indices, 512);
  EXPECT_EQ(a.view_projection, b.view_projection);
  EXPECT_EQ(a.z0, b.z0);
  EXPECT_EQ(a.z1, b.z1);
}

}  // namespace
}  // namespace penumbra
