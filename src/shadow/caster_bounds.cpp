#include "penumbra/shadow/caster_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "shadow/polygon_clip.hpp"

namespace penumbra {

namespace {

// Triangles per leaf: clipping a few triangles costs about what opening
// their boxes would.
constexpr std::uint32_t kLeafTriangles = 8;

// The bytes from one position to the next (0 for fewer than two).
std::size_t stride_of(PositionSpan vertices) {
  if (vertices.size() < 2) return 0;
  return static_cast<std::size_t>(reinterpret_cast<const char*>(&vertices[1]) -
                                  reinterpret_cast<const char*>(&vertices[0]));
}

glm::vec3 frame_coordinates(const glm::mat4& frame, const glm::vec3& p) {
  return {glm::dot(glm::vec3(matrix_row(frame, 0)), p) + frame[3][0],
          glm::dot(glm::vec3(matrix_row(frame, 1)), p) + frame[3][1],
          glm::dot(glm::vec3(matrix_row(frame, 2)), p) + frame[3][2]};
}

// The least and greatest of dot(xyz, q) + w over the box [lo, hi]: per
// axis, the corner the coefficient's sign picks. A zero coefficient adds
// an exact zero, so a function of one coordinate gives the box's own
// bounds on it, unrounded.
glm::vec2 box_range(const glm::vec4& f, const glm::vec3& lo, const glm::vec3& hi) {
  float least = f.w, greatest = f.w;
  for (int a = 0; a < 3; ++a) {
    const float at_lo = f[a] * lo[a], at_hi = f[a] * hi[a];
    least += std::min(at_lo, at_hi);
    greatest += std::max(at_lo, at_hi);
  }
  return {least, greatest};
}

}  // namespace

CasterHierarchy::CasterHierarchy(PositionSpan vertices, std::span<const std::uint32_t> indices,
                                 const glm::mat4& frame)
    : frame_(frame),
      vertices_(vertices.empty() ? nullptr : &vertices[0]),
      vertex_count_(vertices.size()),
      vertex_stride_(stride_of(vertices)),
      indices_(indices.data()),
      index_count_(indices.size()) {
  std::vector<glm::vec3> in_frame(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    in_frame[v] = frame_coordinates(frame, vertices[v]);
  }
  const std::size_t triangles = indices.size() / 3;
  std::vector<glm::vec3> lo(triangles), hi(triangles), centre(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const glm::vec3 &a = in_frame[indices[3 * t]], &b = in_frame[indices[3 * t + 1]],
                    &c = in_frame[indices[3 * t + 2]];
    lo[t] = glm::min(a, glm::min(b, c));
    hi[t] = glm::max(a, glm::max(b, c));
    centre[t] = 0.5f * (lo[t] + hi[t]);
  }
  order_.resize(triangles);
  std::iota(order_.begin(), order_.end(), 0u);
  if (triangles == 0) return;
  nodes_.reserve(2 * (triangles / kLeafTriangles + 1));

  // Top-down, split at the median of the box centres along the widest
  // axis of their bounds: balanced, so a node's depth is log2 of the count.
  struct Task {
    std::uint32_t node, begin, end;
  };
  std::vector<Task> stack;
  nodes_.push_back({});
  stack.push_back({0, 0, static_cast<std::uint32_t>(triangles)});
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    glm::vec3 box_lo(INFINITY), box_hi(-INFINITY), centre_lo(INFINITY), centre_hi(-INFINITY);
    for (std::uint32_t i = task.begin; i < task.end; ++i) {
      const std::uint32_t t = order_[i];
      box_lo = glm::min(box_lo, lo[t]);
      box_hi = glm::max(box_hi, hi[t]);
      centre_lo = glm::min(centre_lo, centre[t]);
      centre_hi = glm::max(centre_hi, centre[t]);
    }
    nodes_[task.node].lo = box_lo;
    nodes_[task.node].hi = box_hi;
    if (task.end - task.begin <= kLeafTriangles) {
      nodes_[task.node].first = task.begin;
      nodes_[task.node].count = task.end - task.begin;
      continue;
    }
    const glm::vec3 extent = centre_hi - centre_lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t middle = task.begin + (task.end - task.begin) / 2;
    std::nth_element(
        order_.begin() + task.begin, order_.begin() + middle, order_.begin() + task.end,
        [&](std::uint32_t a, std::uint32_t b) { return centre[a][axis] < centre[b][axis]; });
    // The two children side by side; the left one's index is stored.
    const auto left = static_cast<std::uint32_t>(nodes_.size());
    const std::uint32_t right = left + 1;
    nodes_.resize(nodes_.size() + 2);
    nodes_[task.node].first = left;
    nodes_[task.node].count = 0;
    stack.push_back({right, middle, task.end});
    stack.push_back({left, task.begin, middle});
  }
}

bool CasterHierarchy::built_for(PositionSpan vertices, std::span<const std::uint32_t> indices,
                                const glm::mat4& frame) const {
  const void* first = vertices.empty() ? nullptr : &vertices[0];
  return frame == frame_ && first == vertices_ && vertices.size() == vertex_count_ &&
         stride_of(vertices) == vertex_stride_ && indices.data() == indices_ &&
         indices.size() == index_count_;
}

bool CasterHierarchy::depth_range(PositionSpan vertices, std::span<const std::uint32_t> indices,
                                  const CasterBoundsQuery& query, float& zmin, float& zmax) const {
  if (nodes_.empty()) return false;
  // The half-spaces in the frame's coordinates, for the boxes: with q =
  // F p + t, dot(n, p) + w = dot(F^-T n, q) + w - dot(F^-T n, t).
  const glm::mat4 to_world = glm::inverse(frame_);
  std::vector<glm::vec4> boxed(query.half_spaces.size());
  for (std::size_t h = 0; h < boxed.size(); ++h) {
    const glm::vec4& world = query.half_spaces[h];
    // A half-space is a row (n, w) acting on (p, 1) = to_world (q, 1).
    boxed[h] = world * to_world;
  }
  const std::size_t count = boxed.size();
  // Depth a function of one coordinate: a box's bounds on it are its
  // triangles' vertex extremes.
  const glm::vec3 f(query.frame_depth);
  const int zeros = (f.x == 0.0f) + (f.y == 0.0f) + (f.z == 0.0f);
  const bool exact = zeros >= 2;
  bool any = false;
  float skipped_min = INFINITY, skipped_max = -INFINITY;
  std::vector<glm::vec3> polygon, scratch;
  std::vector<std::uint32_t> stack = {0};
  auto take = [&](float lo, float hi) {
    zmin = std::min(zmin, lo);
    zmax = std::max(zmax, hi);
    any = true;
  };
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    bool outside = false, inside = true;
    for (std::size_t h = 0; h < count && !outside; ++h) {
      const glm::vec2 r = box_range(boxed[h], node.lo, node.hi);
      outside = r.y < 0.0f;
      inside = inside && r.x >= 0.0f;
    }
    if (outside) continue;
    const glm::vec2 depth = box_range(query.frame_depth, node.lo, node.hi);
    // Nothing in the box can widen the range found so far (branch and
    // bound): most of a region's boxes end here, unopened.
    if (depth.x >= zmin && depth.y <= zmax) continue;
    const bool in_front = !query.in_front_only || depth.x > 0.0f;
    const float below = query.tolerance.x + query.relative_tolerance.x * std::abs(depth.x);
    const float above = query.tolerance.y + query.relative_tolerance.y * std::abs(depth.y);
    // ... or not by more than the tolerance: its bounds are merged at the
    // end, not compared with (so the errors do not add up: at most twice
    // the tolerance in all).
    if (in_front && depth.x >= zmin - below && depth.y <= zmax + above) {
      skipped_min = std::min(skipped_min, depth.x);
      skipped_max = std::max(skipped_max, depth.y);
      continue;
    }
    // A box inside the region whose bounds are the depth's extremes, or
    // one smaller than the tolerance (in depth and in extent: what it
    // holds lies within that of the region) on each end where it widens
    // the range: its bounds, unopened.
    const glm::vec3 extent = node.hi - node.lo;
    const float spread =
        std::max(depth.y - depth.x, std::max(extent.x, std::max(extent.y, extent.z)));
    const bool near_end_within = depth.x >= zmin - below || spread <= below;
    const bool far_end_within = depth.y <= zmax + above || spread <= above;
    if (in_front && inside && exact) {
      take(depth.x, depth.y);
      continue;
    }
    if (in_front && near_end_within && far_end_within) {
      // An end the box's own spread bounds joins the running range; one
      // within the tolerance of it is merged at the end, as above.
      if (spread <= below) zmin = std::min(zmin, depth.x);
      if (spread > below) skipped_min = std::min(skipped_min, depth.x);
      if (spread <= above) zmax = std::max(zmax, depth.y);
      if (spread > above) skipped_max = std::max(skipped_max, depth.y);
      any = true;
      continue;
    }
    if (node.count == 0) {
      stack.push_back(node.first + 1);
      stack.push_back(node.first);
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      const std::size_t t = 3 * static_cast<std::size_t>(order_[i]);
      polygon.assign({vertices[indices[t]], vertices[indices[t + 1]], vertices[indices[t + 2]]});
      clip_polygon(polygon, query.half_spaces, scratch);
      for (const glm::vec3& p : polygon) {
        const float z = glm::dot(query.world_depth, glm::vec4(p, 1.0f));
        if (query.in_front_only && z <= 0.0f) continue;
        take(z, z);
      }
    }
  }
  if (skipped_min <= skipped_max) take(skipped_min, skipped_max);
  return any;
}

const CasterHierarchy& CasterBoundsCache::bounds(PositionSpan vertices,
                                                 std::span<const std::uint32_t> indices,
                                                 const glm::mat4& frame) {
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (entries_[i]->built_for(vertices, indices, frame)) {
      std::rotate(entries_.begin() + static_cast<std::ptrdiff_t>(i),
                  entries_.begin() + static_cast<std::ptrdiff_t>(i) + 1, entries_.end());
      return *entries_.back();
    }
  }
  if (entries_.size() == kCapacity) entries_.erase(entries_.begin());
  entries_.push_back(std::make_unique<CasterHierarchy>(vertices, indices, frame));
  return *entries_.back();
}

}  // namespace penumbra
