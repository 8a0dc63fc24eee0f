#pragma once
// The example's scene: a box on a ground plane, lit by a spot light and a
// sun, seen from above. Plain constants, so a test can work out where the
// shadows fall (tests/library/embed_example_test.cpp).
#include <glm/glm.hpp>

namespace embed {

inline constexpr float kGroundHalfSize = 8.0f;  // the ground: |x|, |z| <= this, y = 0
inline constexpr glm::vec3 kBoxCenter{0.0f, 1.0f, 0.0f};
inline constexpr glm::vec3 kBoxHalfSize{0.6f, 1.0f, 0.6f};

inline constexpr glm::vec3 kSpotPosition{3.5f, 6.0f, 0.0f};
inline constexpr glm::vec3 kSpotTarget{0.0f, 0.0f, 0.0f};
inline constexpr float kSpotConeDegrees = 40.0f;
inline constexpr glm::vec3 kSpotColor{30.0f, 28.0f, 25.0f};  // intensity: irradiance at 1 m

inline constexpr glm::vec3 kSunDirection{0.8f, -1.0f, 0.45f};  // the way it shines (not unit)
inline constexpr glm::vec3 kSunColor{0.7f, 0.75f, 0.85f};

inline constexpr glm::vec3 kCameraPosition{0.0f, 8.0f, 8.0f};
inline constexpr glm::vec3 kCameraTarget{0.0f, 0.0f, 0.5f};
inline constexpr float kCameraFovDegrees = 45.0f;
inline constexpr float kCameraNear = 1.0f;
inline constexpr float kCameraFar = 40.0f;

}  // namespace embed
