// The terminator model's rise to the smooth surface and the part of it a
// light's direction calls for (src/reference/terminator_offset.hpp).
#include "reference/terminator_offset.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace penumbra {
namespace {

const glm::vec3 kUp{0.0f, 1.0f, 0.0f};

// A flat mesh (vertex normals the triangle's) has no smooth surface above
// its triangles.
TEST(TerminatorOffset, AFlatTriangleDoesNotRise) {
  const glm::vec3 corners[3] = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}};
  const glm::vec3 normals[3] = {kUp, kUp, kUp};
  for (const glm::vec3 w :
       {glm::vec3(1.0f / 3.0f), glm::vec3(0.5f, 0.5f, 0.0f), glm::vec3(0.7f, 0.1f, 0.2f)}) {
    EXPECT_EQ(smooth_surface_rise(corners, normals, w, kUp), 0.0f);
  }
}

// A triangle of a coarse sphere (an icosahedron's face on the unit
// sphere, vertex normals its positions): on a convex mesh the corners'
// tangent planes pass above the corners, so the rise is the lowest plane's
// height over the point, along the interpolated normal: from the face's
// centre, 0.2056 below the sphere, it clears the sphere and stays under
// every corner's tangent plane. The same from the back, with every normal
// turned.
TEST(TerminatorOffset, ACoarseSphereRisesUnderItsCornersTangentPlanes) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  glm::vec3 corners[3] = {glm::normalize(glm::vec3(-1, t, 0)), glm::normalize(glm::vec3(0, 1, t)),
                          glm::normalize(glm::vec3(1, t, 0))};
  const glm::vec3 p = (corners[0] + corners[1] + corners[2]) / 3.0f;
  const glm::vec3 n = glm::normalize(p);
  const float gap = 1.0f - glm::length(p);
  const float rise = smooth_surface_rise(corners, corners, glm::vec3(1.0f / 3.0f), n);
  EXPECT_NEAR(gap, 0.2056f, 1e-3f);
  EXPECT_GE(rise, gap);
  for (const glm::vec3& corner : corners) EXPECT_LE(rise, glm::dot(corner - p, corner));
  const glm::vec3 turned[3] = {-corners[0], -corners[1], -corners[2]};
  EXPECT_FLOAT_EQ(smooth_surface_rise(corners, turned, glm::vec3(1.0f / 3.0f), n), rise);
}

// A leaf card's normals bent 60 degrees outwards describe a dome as high
// as the card is wide; the corners' tangent planes bound the rise to the
// card's own size (it is the grazing rule below that keeps it off a card
// the light faces).
TEST(TerminatorOffset, ABentCardRisesNoMoreThanItsSize) {
  const float side = 0.3f;
  const glm::vec3 corners[3] = {{-0.15f, 0, -0.15f}, {0.15f, 0, 0.15f}, {0.15f, 0, -0.15f}};
  glm::vec3 normals[3];
  for (int k = 0; k < 3; ++k) {
    glm::vec3 out = corners[k];
    normals[k] = 0.5f * kUp + std::sin(glm::radians(60.0f)) * glm::normalize(out);
  }
  for (const glm::vec3 w :
       {glm::vec3(1.0f / 3.0f), glm::vec3(0.5f, 0.5f, 0.0f), glm::vec3(0.1f, 0.1f, 0.8f)}) {
    const float rise = smooth_surface_rise(corners, normals, w, kUp);
    EXPECT_GT(rise, 0.0f);
    EXPECT_LT(rise, side);
  }
}

// All of the rise at grazing light, none where the light faces both the
// shading normal and the triangle by the cutoff's cosine or more, and no
// jump between.
TEST(TerminatorOffset, OnlyGrazingLightLiftsTheRays) {
  const auto towards = [](float elevation_degrees) {
    const float e = glm::radians(elevation_degrees);
    return glm::vec3(std::cos(e), std::sin(e), 0.0f);
  };
  EXPECT_EQ(terminator_offset_amount(kUp, kUp, kUp), 0.0f);
  EXPECT_EQ(terminator_offset_amount(kUp, kUp, towards(30.0f)), 0.0f);
  EXPECT_EQ(terminator_offset_amount(kUp, kUp, towards(2.0f)), 1.0f);
  EXPECT_EQ(terminator_offset_amount(kUp, kUp, towards(-3.0f)), 1.0f);  // below: all of it
  const float at = std::asin(kTerminatorOffsetCutoff);                  // n.l = ng.l = the cutoff
  const glm::vec3 l(std::cos(at), std::sin(at), 0.0f);
  const glm::vec3 below(std::cos(at - 1e-4f), std::sin(at - 1e-4f), 0.0f);
  EXPECT_NEAR(terminator_offset_amount(kUp, kUp, l), 0.0f, 1e-5f);
  EXPECT_NEAR(terminator_offset_amount(kUp, kUp, below), 0.0f, 2e-3f);
  const float half = std::asin(0.75f * kTerminatorOffsetCutoff);
  EXPECT_NEAR(terminator_offset_amount(kUp, kUp, towards(glm::degrees(half))), 0.5f, 1e-4f);
}

}  // namespace
}  // namespace penumbra
