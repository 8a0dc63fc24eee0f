// The error bound of a position rebuilt from the camera's depth buffer
// (render/depth_position_error.hpp), for the renderer's reversed-Z
// projection and, for comparison, a standard-Z one, with the near plane
// at 1e-4 of the far one (the renderer's floor).
#include <gtest/gtest.h>

#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "render/camera_depth.hpp"
#include "render/depth_position_error.hpp"

namespace penumbra {
namespace {

constexpr float kNear = 0.01f, kFar = 100.0f;
constexpr int kSize = 1024;

// The bound over the distance for a surface facing the camera at
// distance z on its axis, seen through `projection` (window depth = NDC z,
// as clip control GL_ZERO_TO_ONE gives).
double relative_bound(const glm::mat4& projection, double z) {
  const glm::dmat4 p(projection);
  const glm::dvec4 clip = p * glm::dvec4(0.0, 0.0, -z, 1.0);
  const double depth = clip.z / clip.w;
  return depth_position_error(glm::inverse(p), glm::dvec2(0.0), depth, glm::vec3(0, 0, 1), kSize,
                              kSize, 8) /
         z;
}

TEST(DepthPositionError, RebuildsThePointItWasGiven) {
  const glm::dmat4 p(camera_perspective(glm::radians(40.0f), 1.5f, kNear, kFar));
  for (const glm::dvec3 point : {glm::dvec3(0.3, -0.2, -0.5), glm::dvec3(-20.0, 5.0, -90.0)}) {
    const glm::dvec4 clip = p * glm::dvec4(point, 1.0);
    const glm::dvec3 back =
        position_from_depth(glm::inverse(p), glm::dvec2(clip) / clip.w, clip.z / clip.w);
    EXPECT_NEAR(glm::distance(back, point), 0.0, 1e-9 * glm::length(point));
  }
  // Reversed-Z: the near plane at depth 1, the far plane at 0.
  const glm::dvec4 near_clip = p * glm::dvec4(0.0, 0.0, -kNear, 1.0);
  const glm::dvec4 far_clip = p * glm::dvec4(0.0, 0.0, -kFar, 1.0);
  EXPECT_NEAR(near_clip.z / near_clip.w, CAMERA_NEAR_DEPTH, 1e-6);
  EXPECT_NEAR(far_clip.z / far_clip.w, CAMERA_FAR_DEPTH, 1e-6);
}

// Reversed-Z bounds a point to under 1e-6 of its distance at every depth;
// standard-Z's depth near 1 gave up to 0.5 % at the far plane.
TEST(DepthPositionError, ReversedZKeepsTheBoundRelativeAtEveryDistance) {
  const float fov = glm::radians(40.0f);
  const glm::mat4 reversed = camera_perspective(fov, 1.0f, kNear, kFar);
  const glm::mat4 standard = glm::perspectiveRH_ZO(fov, 1.0f, kNear, kFar);
  for (const double z : {0.1, 1.0, 10.0, 50.0, 99.0}) {
    const double r = relative_bound(reversed, z), s = relative_bound(standard, z);
    std::printf("distance %5.1f: bound / distance %.2e reversed-Z, %.2e standard-Z\n", z, r, s);
    EXPECT_LT(r, 1e-6) << z;
    EXPECT_GT(r, 2e-7) << z << ": a few ulps of the distance remain";
  }
  EXPECT_GT(relative_bound(standard, 99.0), 4e-3);
}

}  // namespace
}  // namespace penumbra
