#include "scene/smooth_normals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

  // Weld by position: place[v] numbers the distinct positions. The sort
  // moves positions with their vertex numbers (16 bytes, not the 40 of a
  // vertex read through an index at every comparison).
  struct Keyed {
    glm::vec3 position;
    std::uint32_t vertex;
  };
  std::vector<Keyed> order(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) {
    order[v] = {mesh.vertices[v].position, static_cast<std::uint32_t>(v)};
  }
  std::sort(order.begin(), order.end(),
            [](const Keyed& a, const Keyed& b) { return position_less(a.position, b.position); });
  std::vector<std::uint32_t> place(vertex_count);
  std::uint32_t places = 0;
  for (std::size_t i = 0; i < vertex_count; ++i) {
    if (i > 0 && position_less(order[i - 1].position, order[i].position)) ++places;
    place[order[i].vertex] = places;
  }
  if (vertex_count > 0) ++places;
  order = {};
  // Renumbered in the order the vertices first name them, so that the
  // result follows the input's order: the loop below then reads the input
  // front to back (a mesh of millions of vertices read in the sorted
  // positions' order missed the cache at nearly every vertex).
  {
    constexpr std::uint32_t kUnnamed = 0xffffffffu;
    std::vector<std::uint32_t> rename(places, kUnnamed);
    std::uint32_t next = 0;
    for (std::uint32_t& p : place) {
      if (rename[p] == kUnnamed) rename[p] = next++;
      p = rename[p];
    }
  }

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
  std::vector<glm::vec3> area_here, unit_here;  // the faces at one position
  for (std::uint32_t p = 0; p < places; ++p) {
    const std::uint32_t begin = first[p], end = first[p + 1];
    const std::uint32_t count = end - begin;
    const std::size_t first_vertex = out.vertices.size();
    area_here.resize(count);
    unit_here.resize(count);
    glm::vec3 all(0.0f);
    for (std::uint32_t j = 0; j < count; ++j) {
      const std::uint32_t face = corner_at[begin + j] / 3;
      area_here[j] = area_normal[face];
      unit_here[j] = unit_normal[face];
      all += area_here[j];
    }
    const glm::vec3 mean = normalized_or(all, glm::vec3(0.0f, 1.0f, 0.0f));
    // Where every pair of faces (each with itself too) is within the
    // crease angle, every corner's sum is `all`, so its normal is `mean`:
    // a smooth surface, most of a scan, needs half the dot products and
    // none of the sums.
    bool smooth = count <= kMaxCreaseCorners;
    for (std::uint32_t i = 0; smooth && i < count; ++i) {
      for (std::uint32_t j = i; j < count; ++j) {
        if (!(glm::dot(unit_here[i], unit_here[j]) >= min_cos)) {
          smooth = false;
          break;
        }
      }
    }
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t corner = corner_at[i];
      glm::vec3 normal = mean;
      if (!smooth && count <= kMaxCreaseCorners) {
        const glm::vec3 own = unit_here[i - begin];
        glm::vec3 sum(0.0f);
        for (std::uint32_t j = 0; j < count; ++j) {
          if (glm::dot(own, unit_here[j]) >= min_cos) sum += area_here[j];
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
