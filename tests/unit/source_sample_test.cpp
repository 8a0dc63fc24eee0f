// The points of a light's source that --accumulate renders its sub-frames
// from, and the weights the shadow view gives them.
#include <gtest/gtest.h>

#include <cmath>

#include "render/accumulation.hpp"

namespace penumbra {
namespace {

// A spot light's points fill its square (perpendicular to its direction,
// light_size wide, centred on it); each sub-frame keeps the direction.
TEST(SourceSample, SpotPointsFillTheSquare) {
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {1.0f, 5.0f, 2.0f};
  spot.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  ShadowSettings shadow;
  shadow.light_size = 1.5f;
  constexpr int kN = 64;
  glm::dvec3 mean(0.0);
  float widest = 0.0f;
  for (int k = 0; k < kN; ++k) {
    const SourceSample s = source_sample(spot, shadow, k, kN, 0);
    const glm::vec3 offset = s.light.position - spot.position;
    EXPECT_NEAR(glm::dot(offset, spot.direction), 0.0f, 1e-5f);
    EXPECT_EQ(s.light.direction, spot.direction);
    widest = std::max(widest, glm::length(offset));
    mean += glm::dvec3(offset) / double(kN);
  }
  EXPECT_LE(widest, 0.75f * std::sqrt(2.0f) + 1e-5f);
  EXPECT_GT(widest, 0.75f);  // reaches beyond the inscribed circle
  EXPECT_LT(glm::length(mean), 0.02);
  // The same points every run.
  EXPECT_EQ(source_sample(spot, shadow, 5, kN, 0).light.position,
            source_sample(spot, shadow, 5, kN, 0).light.position);
}

// The sun's directions lie within half its angular diameter of its
// direction.
TEST(SourceSample, SunDirectionsFillTheDisc) {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
  ShadowSettings shadow;
  shadow.sun_angle = 10.0f;
  float widest = 0.0f;
  for (int k = 0; k < 64; ++k) {
    const glm::vec3 d = source_sample(sun, shadow, k, 64, 0).light.direction;
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    widest = std::max(widest, std::acos(std::min(1.0f, glm::dot(d, sun.direction))));
  }
  EXPECT_LE(widest, glm::radians(5.0f) + 1e-4f);
  EXPECT_GT(widest, glm::radians(4.0f));
}

}  // namespace
}  // namespace penumbra
