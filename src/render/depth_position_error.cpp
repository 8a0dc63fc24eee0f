#include "render/depth_position_error.hpp"

#include <cmath>

#include "render/camera_depth.hpp"

namespace penumbra {

float depth_position_error(const glm::dmat4& inverse_view_projection, glm::dvec2 ndc_xy,
                           double window_depth, glm::vec3 normal, int width, int height,
                           int subpixel_bits) {
  auto world = [&](glm::dvec2 xy, double depth) {
    return position_from_depth(inverse_view_projection, xy, depth);
  };
  const glm::dvec3 n(normal);
  const glm::dvec3 p = world(ndc_xy, window_depth);
  // The camera's centre: the one point every clip-space point (0, 0, z, 0)
  // maps to, for any perspective projection.
  const glm::dvec4 eye_h = inverse_view_projection * glm::dvec4(0.0, 0.0, 1.0, 0.0);
  const glm::dvec3 eye = glm::dvec3(eye_h) / eye_h.w;
  // One subpixel step in NDC units (NDC spans 2 across the viewport).
  const double step = std::ldexp(1.0, -subpixel_bits);
  const glm::dvec2 dx(2.0 * step / width, 0.0), dy(0.0, 2.0 * step / height);
  const double along_depth =
      std::abs(glm::dot(n, world(ndc_xy, window_depth * (1.0 + kDepthRelativeError)) - p));
  const double along_distance = kDistanceRelativeError * std::abs(glm::dot(n, p - eye));
  const double along_x = std::abs(glm::dot(n, world(ndc_xy + dx, window_depth) - p));
  const double along_y = std::abs(glm::dot(n, world(ndc_xy + dy, window_depth) - p));
  return static_cast<float>(along_depth + along_distance + along_x + along_y);
}

}  // namespace penumbra
