#include "penumbra/shadow/light_view.hpp"

#include <gtest/gtest.h>

#include "scene/builtin_scenes.hpp"
#include "scene/mesh.hpp"

namespace penumbra {
namespace {

// Every vertex of the scene projects inside the directional light's
// orthographic frustum, and its relative depth lies in [0, 1].
TEST(LightView, DirectionalFitEnclosesTheScene) {
  Scene scene = *builtin_scene("default");
  TriangleMesh mesh = build_scene_mesh(scene);
  for (const glm::vec3 direction : {glm::vec3(-0.55f, -1.0f, -0.35f), glm::vec3(0.0f, -1.0f, 0.0f),
                                    glm::vec3(1.0f, -0.2f, 0.3f)}) {
    Light light;
    light.type = LightType::Directional;
    light.direction = glm::normalize(direction);
    LightView lv = fit_light_view(light, mesh, 1024);
    EXPECT_FALSE(lv.perspective);
    EXPECT_LT(lv.z0, lv.z1);
    for (const Vertex& v : mesh.vertices) {
      glm::vec4 clip = lv.view_projection * glm::vec4(v.position, 1.0f);
      glm::vec3 ndc = glm::vec3(clip) / clip.w;
      ASSERT_LE(std::abs(ndc.x), 1.0f);
      ASSERT_LE(std::abs(ndc.y), 1.0f);
      ASSERT_LE(std::abs(ndc.z), 1.0f);
      float z = lv.relative_depth(v.position);
      ASSERT_GE(z, 0.0f);
      ASSERT_LE(z, 1.0f);
      // The orthographic depth buffer value equals z-bar.
      ASSERT_NEAR(ndc.z * 0.5f + 0.5f, z, 1e-5f);
    }
  }
}

// Every surface point inside the spot light's frustum has z-bar in [0, 1],
// and the fit is tight: some point lies near each end of the range.
// Points are sampled densely over every triangle, since the ground's
// vertices lie outside the cone.
TEST(LightView, SpotFitHugsTheGeometryInsideTheCone) {
  Scene scene = *builtin_scene("default");
  TriangleMesh mesh = build_scene_mesh(scene);
  const Light& spot = scene.lights.at(0);
  ASSERT_EQ(spot.type, LightType::Spot);
  LightView lv = fit_light_view(spot, mesh, 1024);
  EXPECT_TRUE(lv.perspective);
  float lo = 1.0f, hi = 0.0f;
  int inside = 0;
  const int n = 24;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.vertices[mesh.indices[t]].position;
    const glm::vec3 b = mesh.vertices[mesh.indices[t + 1]].position;
    const glm::vec3 c = mesh.vertices[mesh.indices[t + 2]].position;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        glm::vec3 p = a + (b - a) * (float(i) / n) + (c - a) * (float(j) / n);
        glm::vec4 clip = lv.view_projection * glm::vec4(p, 1.0f);
        if (clip.w <= 0.0f || std::abs(clip.x) > clip.w || std::abs(clip.y) > clip.w) continue;
        ++inside;
        float z = lv.relative_depth(p);
        ASSERT_GE(z, 0.0f);
        ASSERT_LE(z, 1.0f);
        lo = std::min(lo, z);
        hi = std::max(hi, z);
      }
    }
  }
  EXPECT_GT(inside, 1000);
  EXPECT_LT(lo, 0.03f);
  EXPECT_GT(hi, 0.97f);
}

// A texel of a spot light's map at depth d spans d * texel_world.
TEST(LightView, SpotTexelSizeMatchesTheFrustum) {
  Light spot;
  spot.position = {0, 10, 0};
  spot.direction = {0, -1, 0};
  spot.cone_degrees = 45.0f;
  std::vector<Vertex> ground = {
      {{-5, 0, -5}, {0, 1, 0}, 0}, {{5, 0, 5}, {0, 1, 0}, 0}, {{5, 0, -5}, {0, 1, 0}, 0}};
  std::vector<std::uint32_t> triangle = {0, 1, 2};
  LightView lv = fit_light_view(spot, ground, triangle, 512);
  // 90 degree field of view: the frustum is 2 * depth wide.
  EXPECT_NEAR(lv.texel_world * 512.0f, 2.0f, 1e-4f);
}

}  // namespace
}  // namespace penumbra
