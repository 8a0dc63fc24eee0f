#pragma once
// Bounds over a caster set's triangles, so that fitting a view's depth
// range when the camera moves costs what the view's boundary crosses, not
// the triangle count: a bounding-volume hierarchy built once per caster set
// and frame (a cascade's light rotation, the world for the camera), its
// boxes axis-aligned in that frame. Pure CPU, tested without a GPU.
//
// A depth-range query visits a node only if its box meets every half-space;
// a box inside all of them gives its depth extremes at once (exact when the
// depth is a coordinate of the frame: the box holds its triangles' vertex
// extremes), a leaf that crosses a boundary clips its triangles as
// for_each_clipped_triangle() does, and a crossing box whose depth spans
// less than the query's tolerance gives its extremes unclipped (a bound
// that errs outwards, by about the tolerance).
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <vector>

#include "penumbra/position_span.hpp"

namespace penumbra {

struct CasterBoundsQuery {
  // The region: points p with dot(h.xyz, p) + h.w >= 0 for each h (world).
  std::span<const glm::vec4> half_spaces;
  // The depth measured, dot(xyz, p) + w: in world coordinates (for the
  // clipped triangles), and the same function of the frame's coordinates
  // (for the boxes; give it exactly, e.g. (0, 0, -1, 0) for a view's depth,
  // to have boxes inside the region give exact extremes).
  glm::vec4 world_depth{0.0f};
  glm::vec4 frame_depth{0.0f};
  // How far the range may err, outwards, at its near (x) and far (y) end:
  // t = tolerance + relative_tolerance * |the depth there|. A box is
  // opened only where its bounds could widen the range by more than t, or
  // while it is larger than t: the range holds that of the parts inside
  // the region, within that of the parts within t of it widened by 2 t.
  // Zero: exact (for a depth the frame holds as a coordinate).
  glm::vec2 tolerance{0.0f};
  glm::vec2 relative_tolerance{0.0f};
  // Only depths > 0 count (in front of an eye), as frustum_depth_range()
  // has it; boxes reaching depth 0 are opened down to their triangles.
  bool in_front_only = false;
};

class CasterHierarchy {
 public:
  CasterHierarchy() = default;
  // The hierarchy over the triangles `indices` of `vertices`, its boxes
  // axis-aligned in `frame` (an affine map; row r of frame * (p, 1) is a
  // point's coordinate r). Keeps no reference to the arrays.
  CasterHierarchy(PositionSpan vertices, std::span<const std::uint32_t> indices,
                  const glm::mat4& frame);

  // Whether it was built over these arrays (their address, size, stride)
  // in this frame.
  [[nodiscard]] bool built_for(PositionSpan vertices, std::span<const std::uint32_t> indices,
                               const glm::mat4& frame) const;

  // Widens [zmin, zmax] by the depth of the triangles' parts inside the
  // query's region; given an empty range (zmin > zmax), false if there
  // are none. Boxes whose depth lies inside the range found so far are not
  // opened (branch and bound), so a large region costs about what its
  // extremes and its edges do. `vertices` and `indices`: the arrays it was
  // built over.
  bool depth_range(PositionSpan vertices, std::span<const std::uint32_t> indices,
                   const CasterBoundsQuery& query, float& zmin, float& zmax) const;

  [[nodiscard]] std::size_t node_count() const { return nodes_.size(); }

 private:
  struct Node {
    glm::vec3 lo{0.0f}, hi{0.0f};  // box in the frame
    std::uint32_t first = 0;       // leaf: first triangle in order_; inner: left child
    std::uint32_t count = 0;       // leaf: triangle count; 0: inner (right child: first + 1)
  };
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> order_;  // triangle numbers, leaf by leaf
  glm::mat4 frame_{1.0f};
  const void* vertices_ = nullptr;
  std::size_t vertex_count_ = 0, vertex_stride_ = 0;
  const void* indices_ = nullptr;
  std::size_t index_count_ = 0;
};

// The hierarchies of one caster set in the few frames a renderer needs
// (each directional light's, and the world's), built on first use and
// kept while the arrays (address, size, stride) and the frame stay the
// same: a client that changes its casters in place passes new arrays.
class CasterBoundsCache {
 public:
  // The hierarchy for these arrays in this frame; valid until the cache
  // builds kCapacity others.
  const CasterHierarchy& bounds(PositionSpan vertices, std::span<const std::uint32_t> indices,
                                const glm::mat4& frame);

  // Forgets every hierarchy: for arrays whose contents changed in place
  // (the cache knows them by address, size and stride).
  void clear() { entries_.clear(); }

  static constexpr std::size_t kCapacity = 6;

 private:
  std::vector<std::unique_ptr<CasterHierarchy>> entries_;  // least recently used first
};

}  // namespace penumbra
