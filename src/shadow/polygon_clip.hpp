#pragma once
// Clipping the scene's triangles to convex regions (a light's frustum, a
// cascade's column, a slice of the camera's frustum) to measure the depth
// range of the geometry inside: shadow views fit their depth bounds to it.
// Pure CPU functions, tested without a GPU.
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace penumbra {

// A half-space {p : dot(xyz, p) + w >= 0}.
using HalfSpace = glm::vec4;

// The half-space of points whose coordinate `row . (p, 1)` is at least `lo`
// (row: a row of an affine transform, e.g. one axis of a view matrix).
HalfSpace coordinate_at_least(const glm::vec4& row, float lo);
// ... and at most `hi`.
HalfSpace coordinate_at_most(const glm::vec4& row, float hi);

// Row r of a matrix (glm stores columns): the coordinate r of M (p, 1) as
// an affine function of p, ready for coordinate_at_least/most.
glm::vec4 matrix_row(const glm::mat4& m, int r);

// The four side half-spaces |x| <= kx depth, |y| <= ky depth of the
// frustum of a view matrix that looks down -z (depth = -z).
std::array<HalfSpace, 4> frustum_sides(const glm::mat4& view, float kx, float ky);

// Clips the convex polygon `polygon` (in place) to the intersection of the
// half-spaces (Sutherland and Hodgman, "Reentrant Polygon Clipping", CACM
// 1974). `scratch` is working storage, so a loop over many triangles
// allocates nothing. An empty result means the polygon lies outside.
void clip_polygon(std::vector<glm::vec3>& polygon, std::span<const HalfSpace> half_spaces,
                  std::vector<glm::vec3>& scratch);

// Bit h set: the point is inside half_spaces[h] (at most 8 of them), with
// the very test clip_polygon makes.
inline unsigned inside_mask(const glm::vec3& p, std::span<const HalfSpace> half_spaces) {
  unsigned mask = 0;
  for (std::size_t h = 0; h < half_spaces.size(); ++h) {
    if (glm::dot(glm::vec3(half_spaces[h]), p) + half_spaces[h].w >= 0.0f) mask |= 1u << h;
  }
  return mask;
}

// Calls visit(polygon) with the part of each triangle inside the
// half-spaces, for the triangles with a non-empty part. Each vertex is
// tested once (a vertex is shared by about six triangles): a triangle
// whose corners are all inside is visited as it is and one whose corners
// are all outside one half-space is skipped, without clipping; only the
// triangles that cross a boundary are clipped.
template <class Vertices, class Indices, class Visit>
void for_each_clipped_triangle(const Vertices& vertices, const Indices& indices,
                               std::span<const HalfSpace> half_spaces, Visit&& visit) {
  std::vector<glm::vec3> polygon, scratch;
  std::vector<std::uint8_t> inside;
  const bool masks = half_spaces.size() <= 8;
  const unsigned all = (1u << half_spaces.size()) - 1u;
  if (masks) {
    inside.resize(vertices.size());
    for (std::size_t v = 0; v < vertices.size(); ++v) {
      inside[v] = static_cast<std::uint8_t>(inside_mask(vertices[v].position, half_spaces));
    }
  }
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const auto a = indices[t], b = indices[t + 1], c = indices[t + 2];
    polygon.assign({vertices[a].position, vertices[b].position, vertices[c].position});
    if (masks) {
      const unsigned in_all = inside[a] & inside[b] & inside[c];
      const unsigned in_any = inside[a] | inside[b] | inside[c];
      if (in_any != all) continue;  // all three outside one half-space
      if (in_all != all) clip_polygon(polygon, half_spaces, scratch);
    } else {
      clip_polygon(polygon, half_spaces, scratch);
    }
    if (!polygon.empty()) visit(polygon);
  }
}

}  // namespace penumbra
