#include "shadow/polygon_clip.hpp"

#include <utility>

namespace penumbra {

HalfSpace coordinate_at_least(const glm::vec4& row, float lo) {
  return {row.x, row.y, row.z, row.w - lo};
}

HalfSpace coordinate_at_most(const glm::vec4& row, float hi) {
  return {-row.x, -row.y, -row.z, hi - row.w};
}

glm::vec4 matrix_row(const glm::mat4& m, int r) {
  return {m[0][r], m[1][r], m[2][r], m[3][r]};
}

std::array<HalfSpace, 4> frustum_sides(const glm::mat4& view, float kx, float ky) {
  const glm::vec4 x = matrix_row(view, 0), y = matrix_row(view, 1), depth = -matrix_row(view, 2);
  return {coordinate_at_least(kx * depth - x, 0.0f), coordinate_at_least(kx * depth + x, 0.0f),
          coordinate_at_least(ky * depth - y, 0.0f), coordinate_at_least(ky * depth + y, 0.0f)};
}

void clip_polygon(std::vector<glm::vec3>& polygon, std::span<const HalfSpace> half_spaces,
                  std::vector<glm::vec3>& scratch) {
  // A polygon inside every half-space is its own result, one outside
  // any of them has none: most of a scene's triangles are one or the other.
  if (half_spaces.size() <= 8 && !polygon.empty()) {
    const unsigned all = (1u << half_spaces.size()) - 1u;
    unsigned in_all = all, in_any = 0;
    for (const glm::vec3& p : polygon) {
      const unsigned mask = inside_mask(p, half_spaces);
      in_all &= mask;
      in_any |= mask;
    }
    if (in_all == all) return;
    if (in_any != all) {
      polygon.clear();
      return;
    }
  }
  for (const HalfSpace& h : half_spaces) {
    if (polygon.empty()) return;
    const glm::vec3 n(h);
    scratch.clear();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const glm::vec3& a = polygon[i];
      const glm::vec3& b = polygon[(i + 1) % polygon.size()];
      const float da = glm::dot(n, a) + h.w, db = glm::dot(n, b) + h.w;
      if (da >= 0.0f) scratch.push_back(a);
      if ((da >= 0.0f) != (db >= 0.0f)) scratch.push_back(a + (b - a) * (da / (da - db)));
    }
    std::swap(polygon, scratch);
  }
}

}  // namespace penumbra
