#include "render/camera_depth.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra {

static_assert(CAMERA_NEAR_DEPTH == 1.0 && CAMERA_FAR_DEPTH == 0.0,
              "camera_perspective() maps the near plane to 1 and the far plane to 0");

glm::mat4 camera_perspective(float fov_y, float aspect, float near_plane, float far_plane) {
  // GLM's zero-to-one projection maps its first plane to depth 0 and its
  // second to 1: given the far plane first, 0 lands on the far plane.
  return glm::perspectiveRH_ZO(fov_y, aspect, far_plane, near_plane);
}

glm::dvec3 position_from_depth(const glm::dmat4& inverse_projection, glm::dvec2 ndc_xy,
                               double depth) {
  // Clip control GL_ZERO_TO_ONE with glDepthRange(0, 1): window depth is
  // NDC z itself.
  const glm::dvec4 p = inverse_projection * glm::dvec4(ndc_xy, depth, 1.0);
  return glm::dvec3(p) / p.w;
}

}  // namespace penumbra
