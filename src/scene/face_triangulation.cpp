#include "scene/face_triangulation.hpp"

#include <cmath>
#include <numbers>

namespace penumbra {

namespace {

// Assimp's quad test (TriangulateProcess.cpp, 5.2): corner i is concave
// when the angles from its two edges to the diagonal through it add up to
// more than pi. Done in float, as there, so that both pick the same corner.
int concave_quad_corner(std::span<const std::uint32_t> q, const std::vector<Vertex>& vertices) {
  const auto unit = [](glm::vec3 v) {
    const float length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return length != 0.0f ? v / length : v;
  };
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 v = vertices[q[i]].position;
    const glm::vec3 left = unit(vertices[q[(i + 3) % 4]].position - v);
    const glm::vec3 diagonal = unit(vertices[q[(i + 2) % 4]].position - v);
    const glm::vec3 right = unit(vertices[q[(i + 1) % 4]].position - v);
    const float angle = std::acos(glm::dot(left, diagonal)) + std::acos(glm::dot(right, diagonal));
    if (angle > std::numbers::pi_v<float>) return i;
  }
  return 0;
}

// Convex: every corner turns the same way about the polygon's normal
// (Newell's method, robust for non-planar polygons).
bool convex(std::span<const std::uint32_t> corners, const std::vector<Vertex>& vertices) {
  const std::size_t n = corners.size();
  glm::vec3 normal(0.0f);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 a = vertices[corners[i]].position;
    const glm::vec3 b = vertices[corners[(i + 1) % n]].position;
    normal +=
        glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 a = vertices[corners[i]].position;
    const glm::vec3 b = vertices[corners[(i + 1) % n]].position;
    const glm::vec3 c = vertices[corners[(i + 2) % n]].position;
    if (glm::dot(glm::cross(b - a, c - b), normal) < 0.0f) return false;
  }
  return true;
}

}  // namespace

bool append_face_triangles(std::span<const std::uint32_t> corners,
                           const std::vector<Vertex>& vertices,
                           std::vector<std::uint32_t>& indices) {
  const std::size_t n = corners.size();
  if (n < 3) return false;
  if (n == 3) {
    indices.insert(indices.end(), corners.begin(), corners.end());
    return true;
  }
  if (n == 4) {
    const int s = concave_quad_corner(corners, vertices);
    indices.insert(indices.end(), {corners[s], corners[(s + 1) % 4], corners[(s + 2) % 4],
                                   corners[s], corners[(s + 2) % 4], corners[(s + 3) % 4]});
    return true;
  }
  if (!convex(corners, vertices)) return false;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    indices.insert(indices.end(), {corners[0], corners[i], corners[i + 1]});
  }
  return true;
}

}  // namespace penumbra
