#include "reference/terminator_offset.hpp"

#include <algorithm>

namespace penumbra {

float smooth_surface_rise(const glm::vec3 corners[3], const glm::vec3 normals[3],
                          const glm::vec3& w, const glm::vec3& n) {
  const glm::vec3 raw = w.x * normals[0] + w.y * normals[1] + w.z * normals[2];
  // The corners' normals on n's side, all turned at once (as Cycles turns
  // its result for a back face), so that the patch keeps its shape.
  const float side = glm::dot(raw, n) < 0.0f ? -1.0f : 1.0f;
  const glm::vec3 v0 = corners[0], v1 = corners[1], v2 = corners[2];
  const glm::vec3 n0 = side * normals[0], n1 = side * normals[1], n2 = side * normals[2];
  const glm::vec3 p = w.x * v0 + w.y * v1 + w.z * v2;
  // The quadratic patch: zero at the corners, its slopes along the edges
  // those of the corners' normals.
  const float a = glm::dot(n2 - n0, v0 - v2);
  const float b = glm::dot(n2 - n1, v1 - v2);
  const float c = glm::dot(n1 - n0, v1 - v0);
  const float u = w.x, v = w.y;
  const float quadratic = a * u * (u - 1.0f) + (a + b + c) * u * v + b * v * (v - 1.0f);
  // Each corner's tangent plane, raised to pass above the other corners.
  const float e0 = std::max({glm::dot(v1 - v0, n0), glm::dot(v2 - v0, n0), 0.0f});
  const float e1 = std::max({glm::dot(v0 - v1, n1), glm::dot(v2 - v1, n1), 0.0f});
  const float e2 = std::max({glm::dot(v0 - v2, n2), glm::dot(v1 - v2, n2), 0.0f});
  const float h0 = std::max(glm::dot(v0 - p, n0) + e0, 0.0f);
  const float h1 = std::max(glm::dot(v1 - p, n1) + e1, 0.0f);
  const float h2 = std::max(glm::dot(v2 - p, n2) + e2, 0.0f);
  const float h = std::max(std::min({h0, h1, h2}), 0.5f * quadratic);
  return std::max(h, 0.0f) * glm::length(raw);
}

float terminator_offset_amount(const glm::vec3& n, const glm::vec3& ng, const glm::vec3& l) {
  const float nl = std::max(glm::dot(n, l), 0.0f), ngl = glm::dot(ng, l);
  const float amount = nl < kTerminatorOffsetCutoff ? 2.0f - (ngl + nl) / kTerminatorOffsetCutoff
                                                    : 1.0f - ngl / kTerminatorOffsetCutoff;
  return std::clamp(amount, 0.0f, 1.0f);
}

}  // namespace penumbra
