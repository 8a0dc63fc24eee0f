// Depth ranges through the bounds hierarchy (caster_bounds.hpp) against
// the clipping of every triangle it replaces: exact where the depth is a
// coordinate of the hierarchy's frame and no tolerance is allowed, within
// the tolerance and outwards otherwise; and built once per caster set.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "penumbra/shadow/cascades.hpp"
#include "penumbra/shadow/caster_bounds.hpp"
#include "shadow/polygon_clip.hpp"

namespace penumbra {
namespace {

// A bumpy height field of 2 n^2 triangles over [-10, 10]^2.
struct Terrain {
  std::vector<glm::vec3> vertices;
  std::vector<std::uint32_t> indices;
};

Terrain terrain(int n) {
  Terrain t;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const float x = -10.0f + 20.0f * static_cast<float>(i) / n;
      const float z = -10.0f + 20.0f * static_cast<float>(j) / n;
      t.vertices.emplace_back(x, 1.5f * std::sin(0.7f * x) * std::cos(0.5f * z), z);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto a = static_cast<std::uint32_t>(j * (n + 1) + i);
      const auto c = a + static_cast<std::uint32_t>(n + 1);
      for (std::uint32_t k : {a, c, c + 1, a, c + 1, a + 1}) t.indices.push_back(k);
    }
  }
  return t;
}

// Every triangle clipped, as the fits did before the hierarchy.
bool clipped_range(const Terrain& t, std::span<const HalfSpace> region, const glm::vec4& depth,
                   float& zmin, float& zmax) {
  bool any = false;
  for_each_clipped_triangle(t.vertices, t.indices, region, [&](const std::vector<glm::vec3>& p) {
    for (const glm::vec3& q : p) {
      const float z = glm::dot(depth, glm::vec4(q, 1.0f));
      zmin = std::min(zmin, z);
      zmax = std::max(zmax, z);
      any = true;
    }
  });
  return any;
}

glm::mat4 light_frame() {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
  return cascade_light_frame(sun);
}

// Square columns along the light, at random places and sizes.
std::vector<std::array<HalfSpace, 4>> random_columns(const glm::mat4& frame, int count) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> centre(-9.0f, 9.0f), half(0.05f, 6.0f);
  std::vector<std::array<HalfSpace, 4>> columns;
  for (int k = 0; k < count; ++k) {
    const glm::vec4 x = matrix_row(frame, 0), y = matrix_row(frame, 1);
    const float cx = centre(rng), cy = centre(rng), h = half(rng);
    columns.push_back({coordinate_at_least(x, cx - h), coordinate_at_most(x, cx + h),
                       coordinate_at_least(y, cy - h), coordinate_at_most(y, cy + h)});
  }
  return columns;
}

TEST(CasterHierarchy, LightDepthInAColumnIsExactWithoutTolerance) {
  const Terrain t = terrain(40);
  const glm::mat4 frame = light_frame();
  const CasterHierarchy bounds(t.vertices, t.indices, frame);
  const glm::vec4 depth = -matrix_row(frame, 2);
  int nonempty = 0;
  for (const auto& column : random_columns(frame, 200)) {
    float lo = 1e30f, hi = -1e30f, expected_lo = 1e30f, expected_hi = -1e30f;
    const CasterBoundsQuery query{.half_spaces = column,
                                  .world_depth = depth,
                                  .frame_depth = glm::vec4(0.0f, 0.0f, -1.0f, 0.0f)};
    const bool found = bounds.depth_range(t.vertices, t.indices, query, lo, hi);
    ASSERT_EQ(found, clipped_range(t, column, depth, expected_lo, expected_hi));
    EXPECT_EQ(lo, expected_lo);
    EXPECT_EQ(hi, expected_hi);
    nonempty += found;
  }
  EXPECT_GT(nonempty, 100);
}

// The terrain's slope along the light stays under 2, so what lies within
// the tolerance t of a column is within 2 t of its depth range, and the
// range errs by at most 2 t + 2 t.
TEST(CasterHierarchy, ToleranceWidensTheRangeOutwardsOnly) {
  const Terrain t = terrain(120);
  const glm::mat4 frame = light_frame();
  const CasterHierarchy bounds(t.vertices, t.indices, frame);
  const glm::vec4 depth = -matrix_row(frame, 2);
  for (const auto& column : random_columns(frame, 100)) {
    float expected_lo = 1e30f, expected_hi = -1e30f;
    if (!clipped_range(t, column, depth, expected_lo, expected_hi)) continue;
    for (float tolerance : {0.01f, 0.1f, 1.0f}) {
      float lo = 1e30f, hi = -1e30f;
      const CasterBoundsQuery query{.half_spaces = column,
                                    .world_depth = depth,
                                    .frame_depth = glm::vec4(0.0f, 0.0f, -1.0f, 0.0f),
                                    .tolerance = glm::vec2(tolerance)};
      ASSERT_TRUE(bounds.depth_range(t.vertices, t.indices, query, lo, hi));
      EXPECT_LE(lo, expected_lo);
      EXPECT_GE(lo, expected_lo - 4.0f * tolerance);
      EXPECT_GE(hi, expected_hi);
      EXPECT_LE(hi, expected_hi + 4.0f * tolerance);
    }
  }
}

// The camera's planes: a depth the world frame does not hold as a
// coordinate, in front of the eye only. Outwards always; the near end,
// where depth precision is decided, within a few of its tolerances (1/32);
// the far end (1/8 of its depth) may also take in what lies that close
// outside the frustum's sides, which run nearly along the depth.
TEST(CasterHierarchy, CameraFrustumDepthWithinItsRelativeTolerance) {
  const Terrain t = terrain(120);
  const CasterHierarchy bounds(t.vertices, t.indices, glm::mat4(1.0f));
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-8.0f, 8.0f);
  for (int k = 0; k < 50; ++k) {
    const glm::vec3 eye(u(rng), 3.0f + 0.3f * u(rng), u(rng));
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(u(rng), 0.0f, u(rng)), glm::vec3(0, 1, 0));
    float lo = 1e30f, hi = 0.0f, expected_lo = 1e30f, expected_hi = 0.0f;
    const bool expected =
        frustum_depth_range(view, 0.6f, 0.4f, t.vertices, t.indices, expected_lo, expected_hi);
    ASSERT_EQ(frustum_depth_range(view, 0.6f, 0.4f, t.vertices, t.indices, bounds, lo, hi),
              expected);
    if (!expected) continue;
    EXPECT_LE(lo, expected_lo);
    EXPECT_GE(lo, expected_lo * (1.0f - 4.0f / 32.0f) - 1e-5f);
    EXPECT_GE(hi, expected_hi);
    EXPECT_LE(hi, 2.0f * expected_hi);
  }
}

TEST(CasterHierarchy, CacheBuildsOncePerArraysAndFrame) {
  const Terrain t = terrain(10), other = terrain(10);
  CasterBoundsCache cache;
  const glm::mat4 frame = light_frame();
  const CasterHierarchy& first = cache.bounds(t.vertices, t.indices, frame);
  EXPECT_TRUE(first.built_for(t.vertices, t.indices, frame));
  EXPECT_EQ(&cache.bounds(t.vertices, t.indices, frame), &first);
  EXPECT_FALSE(first.built_for(other.vertices, other.indices, frame));
  EXPECT_FALSE(first.built_for(t.vertices, t.indices, glm::mat4(1.0f)));
  const CasterHierarchy& world = cache.bounds(t.vertices, t.indices, glm::mat4(1.0f));
  EXPECT_TRUE(world.built_for(t.vertices, t.indices, glm::mat4(1.0f)));
  EXPECT_EQ(&cache.bounds(t.vertices, t.indices, frame), &first) << "kept beside the other";
  // A leaf holds a few triangles: the hierarchy is about a quarter the
  // size of the triangle list, not a copy of it.
  EXPECT_LT(world.node_count(), t.indices.size() / 3);
}

}  // namespace
}  // namespace penumbra
