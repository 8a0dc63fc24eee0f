#include "scene/smooth_normals.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace penumbra {

namespace {

bool position_less(const glm::vec3& a, const glm::vec3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

glm::vec3 normalized_or(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return std::isfinite(length) && length > 0.0f ? v / length : fallback;
}

}  // namespace

TriangleMesh with_smooth_normals(const TriangleMesh& mesh, float crease_degrees) {
  const std::size_t vertex_count = mesh.vertices.size();
  const std::size_t corner_count = mesh.indices.size();
  const std::size_t face_count = corner_count / 3;

  // Weld by position: place[v] numbers the distinct positions.
  std::vector<std::uint32_t> order(vertex_count);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return position_less(mesh.vertices[a].position, mesh.vertices[b].position);
  });
  std::vector<std::uint32_t> place(vertex_count);
  std::uint32_t places = 0;
  for (std::size_t i = 0; i < vertex_count; ++i) {
    if (i > 0 &&
        position_less(mesh.vertices[order[i - 1]].position, mesh.vertices[order[i]].position)) {
      ++places;
    }
    place[order[i]] = places;
  }
  if (vertex_count > 0) ++places;

  // Face normals: the cross product's length is twice the area, so sums
  // of them weight by area.
  std::vector<glm::vec3> area_normal(face_count), unit_normal(face_count);
  for (std::size_t f = 0; f < face_count; ++f) {
    const glm::vec3 a = mesh.vertices[mesh.indices[3 * f]].position;
    const glm::vec3 b = mesh.vertices[mesh.indices[3 * f + 1]].position;
    const glm::vec3 c = mesh.vertices[mesh.indices[3 * f + 2]].position;
    area_normal[f] = glm::cross(b - a, c - a);
    unit_normal[f] = normalized_or(area_normal[f], glm::vec3(0.0f));
  }

  // The corners at each position, in compressed rows: corners of place p
  // are corner_at[first[p] .. first[p + 1]).
  std::vector<std::uint32_t> first(places + 1, 0u);
  for (std::uint32_t index : mesh.indices) ++first[place[index] + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<std::uint32_t> corner_at(corner_count);
  {
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (std::size_t c = 0; c < corner_count; ++c) {
      corner_at[next[place[mesh.indices[c]]]++] = static_cast<std::uint32_t>(c);
    }
  }

  // Above this many corners at one position (a fan's apex, a model
  // collapsed to a point), the per-corner search would be quadratic: such
  // corners all take the mean of every triangle there.
  constexpr std::uint32_t kMaxCreaseCorners = 256;
  const float min_cos = std::cos(glm::radians(crease_degrees));
  TriangleMesh out;
  out.vertices.reserve(vertex_count);
  out.indices.resize(corner_count);
  for (std::uint32_t p = 0; p < places; ++p) {
    const std::uint32_t begin = first[p], end = first[p + 1];
    const std::size_t first_vertex = out.vertices.size();
    glm::vec3 all(0.0f);
    for (std::uint32_t j = begin; j < end; ++j) all += area_normal[corner_at[j] / 3];
    const glm::vec3 mean = normalized_or(all, glm::vec3(0.0f, 1.0f, 0.0f));
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t corner = corner_at[i];
      glm::vec3 normal = mean;
      if (end - begin <= kMaxCreaseCorners) {
        const glm::vec3 own = unit_normal[corner / 3];
        glm::vec3 sum(0.0f);
        for (std::uint32_t j = begin; j < end; ++j) {
          const std::uint32_t face = corner_at[j] / 3;
          if (glm::dot(own, unit_normal[face]) >= min_cos) sum += area_normal[face];
        }
        normal = normalized_or(sum, mean);
      }
      const Vertex& source = mesh.vertices[mesh.indices[corner]];
      // Corners that came out alike share a vertex (a handful per position).
      std::size_t v = first_vertex;
      while (v < out.vertices.size() &&
             (out.vertices[v].normal != normal || out.vertices[v].material != source.material ||
              out.vertices[v].uv != source.uv || out.vertices[v].color != source.color)) {
        ++v;
      }
      if (v == out.vertices.size()) {
        Vertex vertex = source;
        vertex.normal = normal;
        out.vertices.push_back(vertex);
      }
      out.indices[corner] = static_cast<std::uint32_t>(v);
    }
  }
  return out;
}

}  // namespace penumbra
