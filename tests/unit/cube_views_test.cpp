// A point light's cube of shadow views: face choice, face matrices, the
// guard band's field of view, the radial depth range.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scene/mesh.hpp"
#include "shadow/cube_views.hpp"

namespace penumbra {
namespace {

TEST(CubeViews, FaceIsTheMajorAxis) {
  for (int face = 0; face < kCubeFaces; ++face) {
    const glm::vec3 axis = cube_face_axis(face);
    EXPECT_EQ(cube_face(axis), face);
    // Off the axis, but still nearest to it.
    EXPECT_EQ(cube_face(axis + 0.4f * cube_face_up(face)), face);
  }
  EXPECT_EQ(cube_face({0.5f, -0.9f, 0.2f}), 3);
  EXPECT_EQ(cube_face({-0.1f, 0.2f, -0.3f}), 5);
}

TEST(CubeViews, GuardBandWidensTheFaceByTheGivenTexels) {
  const int size = 512;
  EXPECT_FLOAT_EQ(guard_band_half_width(size, 0.0f), 1.0f);
  EXPECT_NEAR(guard_band_fov(size, 0.0f), glm::radians(90.0f), 1e-6);
  for (float g : {1.0f, 5.0f, 16.0f, 64.0f}) {
    const float t = guard_band_half_width(size, g);
    // The band beyond the 90-degree face (t - 1 of the projection plane)
    // is g texels of 2t / size each.
    EXPECT_NEAR((t - 1.0f) / (2.0f * t / size), g, 1e-3f) << g;
    EXPECT_GT(guard_band_fov(size, g), glm::radians(90.0f));
  }
}

TEST(CubeViews, GuardBandFollowsTheFilterAndCanBeTurnedOff) {
  ShadowSettings s;
  s.technique = Technique::Vsm;
  s.blur = 6;
  s.normal_offset = 0.5f;
  EXPECT_FLOAT_EQ(guard_band_texels(s, 512), 6.0f + 1.0f + 2.0f);
  s.technique = Technique::Pcf;
  s.pcf_width = 9.0f;
  EXPECT_FLOAT_EQ(guard_band_texels(s, 512), 5.0f + 3.0f);
  s.technique = Technique::Pcss;
  EXPECT_FLOAT_EQ(guard_band_texels(s, 512), 512.0f / 8.0f);  // capped
  s.guard_band = false;
  EXPECT_FLOAT_EQ(guard_band_texels(s, 512), 0.0f);
}

TEST(CubeViews, RadialDepthRangeFindsTheNearestPointInsideATriangle) {
  // A large triangle in the plane y = -2 under a light at the origin: the
  // nearest point is its interior point right below the light.
  std::vector<Vertex> vertices(3);
  vertices[0].position = {-10.0f, -2.0f, -10.0f};
  vertices[1].position = {10.0f, -2.0f, -10.0f};
  vertices[2].position = {0.0f, -2.0f, 10.0f};
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  float zmin = 1e30f, zmax = 0.0f;
  ASSERT_TRUE(radial_depth_range(glm::vec3(0.0f), vertices, indices, zmin, zmax));
  EXPECT_NEAR(zmin, 2.0f, 1e-5f);
  EXPECT_NEAR(zmax, std::sqrt(200.0f + 4.0f), 1e-4f);
}

TEST(CubeViews, EveryDirectionProjectsInsideItsFaceWithRadialDepth) {
  std::vector<Vertex> vertices(3);
  vertices[0].position = {-10.0f, -2.0f, -10.0f};
  vertices[1].position = {10.0f, -2.0f, -10.0f};
  vertices[2].position = {0.0f, 8.0f, 10.0f};
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  Light light;
  light.type = LightType::Point;
  light.position = {0.5f, 1.0f, -0.5f};
  const int size = 256;
  const float guard = 8.0f;
  const std::vector<LightView> views = fit_cube_views(light, vertices, indices, size, guard);
  ASSERT_EQ(views.size(), 6u);
  const float t = guard_band_half_width(size, guard);
  std::mt19937 rng(4);
  std::normal_distribution<float> n(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 d = glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
    const float distance = views[0].z0 + (views[0].z1 - views[0].z0) * 0.5f;
    const glm::vec3 p = light.position + distance * d;
    const LightView& v = views[static_cast<std::size_t>(cube_face(d))];
    const glm::vec4 clip = v.view_projection * glm::vec4(p, 1.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    ASSERT_GT(clip.w, 0.0f);
    // Inside the 90-degree part of the face, leaving the guard band free.
    EXPECT_LE(std::abs(ndc.x), 1.0f / t + 1e-5f);
    EXPECT_LE(std::abs(ndc.y), 1.0f / t + 1e-5f);
    EXPECT_GE(ndc.z, -1.0f);
    EXPECT_LE(ndc.z, 1.0f);
    // Radial depth: the same z-bar from every face that sees the point.
    EXPECT_NEAR(v.depth(p), distance, 1e-4f * distance);
  }
  for (const LightView& v : views) {
    EXPECT_TRUE(v.radial);
    EXPECT_EQ(v.z0, views[0].z0);
    EXPECT_EQ(v.z1, views[0].z1);
    EXPECT_NEAR(v.texel_world, 2.0f * t / size, 1e-7f);
  }
}

}  // namespace
}  // namespace penumbra
