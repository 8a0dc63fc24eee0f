#include "reference/ground_pixels.hpp"

#include <algorithm>
#include <cmath>

#include "scene/mesh.hpp"

namespace penumbra {

namespace {

// A plane shape's frame: its centre, unit axes along its sides and its
// unit normal, and its half extents along the sides.
struct GroundPlane {
  glm::vec3 centre, side_x, side_z, normal;
  float half_x, half_z;
};

GroundPlane ground_plane(const Shape& shape) {
  const glm::mat4 m = shape_transform(shape);
  const glm::vec3 x = glm::vec3(m[0]) * (0.5f * shape.size.x);
  const glm::vec3 z = glm::vec3(m[2]) * (0.5f * shape.size.z);
  const glm::vec3 up = glm::vec3(m[1]);
  return {glm::vec3(m[3]),    glm::normalize(x), glm::normalize(z),
          glm::normalize(up), glm::length(x),    glm::length(z)};
}

}  // namespace

std::vector<std::uint8_t> ground_pixels(const Scene& scene, const SurfacePoints& surfaces) {
  std::vector<GroundPlane> planes;
  for (const Shape& shape : scene.shapes) {
    if (shape.kind == ShapeKind::Plane && shape.size.x > 0.0f && shape.size.z > 0.0f) {
      planes.push_back(ground_plane(shape));
    }
  }
  // A normal within 1 degree of the plane's.
  const float same_direction = std::cos(glm::radians(1.0f));
  std::vector<std::uint8_t> ground(surfaces.size(), 0);
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    if (surfaces.covered[i] == 0) continue;
    const glm::vec3 p = surfaces.position[i];
    for (const GroundPlane& g : planes) {
      const glm::vec3 d = p - g.centre;
      const float off = std::abs(glm::dot(d, g.normal));
      const float tolerance = surfaces.error_bound(i) + 1e-5f * std::max(g.half_x, g.half_z);
      if (off <= tolerance && std::abs(glm::dot(d, g.side_x)) <= g.half_x &&
          std::abs(glm::dot(d, g.side_z)) <= g.half_z &&
          std::abs(glm::dot(surfaces.normal[i], g.normal)) >= same_direction) {
        ground[i] = 1;
        break;
      }
    }
  }
  return ground;
}

}  // namespace penumbra
