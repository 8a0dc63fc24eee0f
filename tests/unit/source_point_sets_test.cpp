// The traced reference's precomputed source points: where they lie for
// each kind of light, and how pixels pick their sets.
#include "reference/source_point_sets.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace penumbra {
namespace {

// A spot light's points fill its square: in the plane through the light
// perpendicular to its direction, within size / 2 of the centre along
// each axis, reaching near the corners; a point light's one point is its
// centre.
TEST(SourcePointSets, SpotPointsFillTheSquare) {
  ReferenceLight light;
  light.position = {1.0f, 4.0f, -2.0f};
  light.direction = {0.0f, -1.0f, 0.0f};
  light.axis_u = {1.0f, 0.0f, 0.0f};
  light.axis_v = {0.0f, 0.0f, 1.0f};
  light.size = 0.8f;
  const SourcePointSets sets(light, 64, 100);
  ASSERT_EQ(sets.kind(), SourcePointKind::SquarePoint);
  ASSERT_EQ(sets.count(), 64u);
  float farthest = 0.0f;
  for (std::uint32_t k = 0; k < sets.set_count(); ++k) {
    const SourcePointSets::Set set = sets.set(k);
    for (std::uint32_t s = 0; s < sets.count(); ++s) {
      const glm::vec3 offset = glm::vec3(set.x[s], set.y[s], set.z[s]) - light.position;
      EXPECT_NEAR(offset.y, 0.0f, 1e-6f);
      EXPECT_LE(std::abs(offset.x), 0.4f + 1e-6f);
      EXPECT_LE(std::abs(offset.z), 0.4f + 1e-6f);
      farthest = std::max(farthest, glm::length(glm::vec2(offset.x, offset.z)));
    }
  }
  EXPECT_GT(farthest, 0.5f);  // beyond the inscribed circle
  light.size = 0.0f;
  const SourcePointSets point(light, 64, 100);
  ASSERT_EQ(point.count(), 1u);
  const SourcePointSets::Set centre = point.set_for(5);
  EXPECT_EQ(glm::vec3(centre.x[0], centre.y[0], centre.z[0]), light.position);
}

// A sun's points are unit directions towards it, within half its angular
// diameter of -direction, reaching near the rim.
TEST(SourcePointSets, SunDirectionsFillTheDisc) {
  ReferenceLight sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  const glm::vec3 helper(1.0f, 0.0f, 0.0f);
  sun.axis_u = glm::normalize(glm::cross(sun.direction, helper));
  sun.axis_v = glm::cross(sun.direction, sun.axis_u);
  sun.size = glm::radians(8.0f);
  const SourcePointSets sets(sun, 256, 16);
  ASSERT_EQ(sets.kind(), SourcePointKind::SunDirection);
  float widest = 0.0f;
  for (std::uint32_t k = 0; k < sets.set_count(); ++k) {
    const SourcePointSets::Set set = sets.set(k);
    for (std::uint32_t s = 0; s < sets.count(); ++s) {
      const glm::vec3 w(set.x[s], set.y[s], set.z[s]);
      EXPECT_NEAR(glm::length(w), 1.0f, 1e-5f);
      widest = std::max(widest, std::acos(std::min(1.0f, glm::dot(w, -sun.direction))));
    }
  }
  EXPECT_LE(widest, glm::radians(4.0f) + 1e-4f);
  EXPECT_GT(widest, glm::radians(3.8f));
}

// A sphere's points are points of the unit disk (mapped onto each
// receiver's cone later).
TEST(SourcePointSets, SpherePointsFillTheUnitDisk) {
  ReferenceLight sphere;
  sphere.type = LightType::Point;
  sphere.size = 0.5f;
  const SourcePointSets sets(sphere, 100, 8);
  ASSERT_EQ(sets.kind(), SourcePointKind::SphereDiskPoint);
  float widest = 0.0f;
  for (std::uint32_t s = 0; s < sets.count(); ++s) {
    const SourcePointSets::Set set = sets.set(3);
    const float r = glm::length(glm::vec2(set.x[s], set.y[s]));
    EXPECT_LE(r, 1.0f + 1e-6f);
    widest = std::max(widest, r);
  }
  EXPECT_GT(widest, 0.9f);
}

// There are no more sets than pixels to use them, and neighbouring pixels
// pick different sets (their noise is unrelated): of a row of 64 pixels
// choosing among 1024 sets, nearly all differ; sets differ from each
// other.
TEST(SourcePointSets, NeighboursPickDifferentSets) {
  ReferenceLight light;
  light.size = 1.0f;
  EXPECT_EQ(SourcePointSets(light, 16, 6).set_count(), 6u);
  const SourcePointSets sets(light, 16, 1u << 20);
  ASSERT_EQ(sets.set_count(), 1024u);
  std::set<const float*> chosen;
  for (std::uint32_t pixel = 1000; pixel < 1064; ++pixel) chosen.insert(sets.set_for(pixel).x);
  EXPECT_GE(chosen.size(), 60u);
  EXPECT_NE(sets.set(0).x[0], sets.set(1).x[0]);
  EXPECT_EQ(sets.set_for(7).x, sets.set_for(7).x);  // reproducible
}

}  // namespace
}  // namespace penumbra
