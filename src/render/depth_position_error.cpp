#include "render/depth_position_error.hpp"

#include <cmath>

namespace penumbra {

float depth_position_error(const glm::dmat4& inverse_view_projection, glm::dvec2 ndc_xy,
                           double window_depth, glm::vec3 normal, int width, int height,
                           int subpixel_bits) {
  auto world = [&](glm::dvec2 xy, double depth) {
    const glm::dvec4 p = inverse_view_projection * glm::dvec4(xy, depth * 2.0 - 1.0, 1.0);
    return glm::dvec3(p) / p.w;
  };
  const glm::dvec3 n(normal);
  const glm::dvec3 p = world(ndc_xy, window_depth);
  // One subpixel step in NDC units (NDC spans 2 across the viewport).
  const double step = std::ldexp(1.0, -subpixel_bits);
  const glm::dvec2 dx(2.0 * step / width, 0.0), dy(0.0, 2.0 * step / height);
  const double along_depth =
      std::abs(glm::dot(n, world(ndc_xy, window_depth + kDepthBufferError) - p));
  const double along_x = std::abs(glm::dot(n, world(ndc_xy + dx, window_depth) - p));
  const double along_y = std::abs(glm::dot(n, world(ndc_xy + dy, window_depth) - p));
  return static_cast<float>(along_depth + along_x + along_y);
}

}  // namespace penumbra
