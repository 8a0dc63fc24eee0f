// The mouse's camera and light controls, as geometry.
#include <gtest/gtest.h>

#include <cmath>

#include "viewer/light_drag.hpp"
#include "viewer/orbit_camera.hpp"

namespace penumbra {
namespace {

Camera start_camera() {
  Camera camera;
  camera.position = {1.0f, 6.5f, 10.5f};
  camera.target = {0.0f, 0.9f, 0.5f};
  camera.fov_y_degrees = 45.0f;
  return camera;
}

glm::vec3 camera_right(const Camera& c) {
  return glm::normalize(glm::cross(c.target - c.position, c.up));
}

TEST(OrbitCamera, IsExactlyTheStartUntilMoved) {
  const Camera start = start_camera();
  OrbitCamera orbit(start);
  EXPECT_EQ(orbit.camera().position, start.position);
  EXPECT_EQ(orbit.camera().target, start.target);
}

TEST(OrbitCamera, OrbitKeepsTargetAndDistanceAndFollowsTheCursor) {
  const Camera start = start_camera();
  OrbitCamera orbit(start);
  const float distance = glm::length(start.position - start.target);
  orbit.orbit(40.0f, 0.0f);  // drag right: the camera moves to its left
  EXPECT_EQ(orbit.camera().target, start.target);
  EXPECT_NEAR(glm::length(orbit.camera().position - start.target), distance, 1e-4f);
  EXPECT_LT(glm::dot(orbit.camera().position - start.position, camera_right(start)), 0.0f);
  EXPECT_NEAR(orbit.camera().position.y, start.position.y, 1e-4f);
  orbit.orbit(0.0f, 30.0f);  // drag down: the camera rises
  EXPECT_GT(orbit.camera().position.y, start.position.y);
  orbit.orbit(0.0f, 1e5f);  // stops short of the pole
  const glm::vec3 view = glm::normalize(orbit.camera().target - orbit.camera().position);
  EXPECT_GT(glm::length(glm::cross(view, glm::vec3(0.0f, 1.0f, 0.0f))), 1e-2f);
}

TEST(OrbitCamera, PanMovesTheTargetInTheViewPlaneByThePixelsDragged) {
  const Camera start = start_camera();
  OrbitCamera orbit(start);
  const int height = 400;
  orbit.pan(-100.0f, 0.0f, height);  // drag left: the scene follows, the camera moves right
  const glm::vec3 moved = orbit.camera().target - start.target;
  const float distance = glm::length(start.position - start.target);
  const float expected = 100.0f * 2.0f * distance * std::tan(glm::radians(22.5f)) / height;
  EXPECT_NEAR(glm::dot(moved, camera_right(start)), expected, 1e-3f);
  EXPECT_NEAR(glm::length(moved), expected, 1e-3f);
  EXPECT_NEAR(glm::length(orbit.camera().position - orbit.camera().target), distance, 1e-4f);
}

TEST(OrbitCamera, ZoomScalesTheDistance) {
  const Camera start = start_camera();
  OrbitCamera orbit(start);
  const float distance = glm::length(start.position - start.target);
  orbit.zoom(2.0f);
  EXPECT_NEAR(glm::length(orbit.camera().position - start.target), distance * 0.81f, 1e-4f);
  orbit.zoom(-2.0f);
  EXPECT_NEAR(glm::length(orbit.camera().position - start.target), distance, 1e-4f);
}

Light spot_light() {
  Light light;
  light.type = LightType::Spot;
  light.position = {3.0f, 8.0f, 2.0f};
  light.direction = glm::normalize(glm::vec3(-3.0f, -8.0f, -2.0f));
  return light;
}

TEST(LightDrag, SpotLightCirclesItsAimPointAndKeepsAimingAtIt) {
  const Light start = spot_light();
  const LightDrag drag(start, glm::vec3(0.0f));
  EXPECT_NEAR(glm::length(drag.pivot()), 0.0f, 1e-5f);  // it aims at the scene's centre
  const glm::vec3 right{1.0f, 0.0f, 0.0f};
  for (float dx : {-300.0f, 25.0f, 500.0f}) {
    for (float dy : {-200.0f, 0.0f, 60.0f}) {
      const Light moved = drag.dragged(dx, dy, right);
      EXPECT_NEAR(glm::length(moved.position - drag.pivot()), glm::length(start.position), 1e-4f);
      EXPECT_NEAR(glm::dot(moved.direction, glm::normalize(drag.pivot() - moved.position)), 1.0f,
                  1e-5f);
    }
  }
  EXPECT_GT(drag.dragged(50.0f, 0.0f, right).position.x, start.position.x);
  EXPECT_LT(drag.dragged(-50.0f, 0.0f, right).position.x, start.position.x);
  EXPECT_LT(drag.dragged(50.0f, 0.0f, -right).position.x, start.position.x);
  EXPECT_GT(drag.dragged(0.0f, -50.0f, right).position.y, start.position.y);  // drag up: higher
  EXPECT_EQ(drag.dragged(0.0f, 0.0f, right).color, start.color);
}

TEST(LightDrag, DirectionalLightTurnsAndStaysShortOfTheZenith) {
  Light start;
  start.type = LightType::Directional;
  start.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
  const LightDrag drag(start, glm::vec3(0.0f));
  const glm::vec3 right{1.0f, 0.0f, 0.0f};
  const Light turned = drag.dragged(100.0f, 0.0f, right);
  EXPECT_NEAR(glm::length(turned.direction), 1.0f, 1e-5f);
  EXPECT_NEAR(turned.direction.y, start.direction.y, 1e-5f);
  // The light moves right, so its light travels more to the left.
  EXPECT_LT(turned.direction.x, start.direction.x);
  const Light overhead = drag.dragged(0.0f, -1e5f, right);
  EXPECT_GT(overhead.direction.y, -1.0f);
  EXPECT_LT(overhead.direction.y, -0.99f);
}

}  // namespace
}  // namespace penumbra
