#include "penumbra/shadow/view_cache.hpp"

#include <algorithm>
#include <cstring>

namespace penumbra {

namespace {

// Whether two views write the same depths: shadow_depth.frag and
// caster_depth.frag read the matrices, the depth range and the kind of
// depth, nothing else (the source's width changes only the lookup). Compared
// bit for bit: a refit that moves a view by one ulp draws it again.
bool same_depths(const ShadowViewData& a, const ShadowViewData& b) {
  return std::memcmp(&a.view, &b.view, sizeof a.view) == 0 &&
         std::memcmp(&a.view_projection, &b.view_projection, sizeof a.view_projection) == 0 &&
         std::memcmp(&a.depth_range, &b.depth_range, sizeof a.depth_range) == 0 &&
         a.radial_depth == b.radial_depth;
}

}  // namespace

bool box_may_be_seen(const glm::mat4& view_projection, const CasterBounds& box) {
  // Outside one plane of the clip volume -w <= x, y <= w with every corner
  // (the frustum culling of Gribb & Hartmann, "Fast Extraction of Viewing
  // Frustum Planes", 2001, applied to the corners in clip space).
  int behind = 0, left = 0, right = 0, below = 0, above = 0;
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                           (c & 4) ? box.max.z : box.min.z);
    const glm::vec4 p = view_projection * glm::vec4(corner, 1.0f);
    behind += p.w <= 0.0f;
    left += p.x < -p.w;
    right += p.x > p.w;
    below += p.y < -p.w;
    above += p.y > p.w;
  }
  return behind < 8 && left < 8 && right < 8 && below < 8 && above < 8;
}

void ViewCache::caster_moved(const CasterBounds& before, const CasterBounds& after) {
  moved_.push_back(before);
  moved_.push_back(after);
}

std::span<const std::uint8_t> ViewCache::stale_views(std::span<const ShadowViewData> views,
                                                     int map_size) {
  const bool all = all_stale_ || map_size != map_size_ || views.size() != drawn_.size();
  stale_.assign(views.size(), all ? 1 : 0);
  if (!all) {
    for (std::size_t i = 0; i < views.size(); ++i) {
      if (!same_depths(views[i], drawn_[i])) {
        stale_[i] = 1;
        continue;
      }
      stale_[i] = std::any_of(moved_.begin(), moved_.end(), [&](const CasterBounds& box) {
        return box_may_be_seen(views[i].view_projection, box);
      });
    }
  }
  drawn_.assign(views.begin(), views.end());
  map_size_ = map_size;
  all_stale_ = false;
  moved_.clear();
  return stale_;
}

}  // namespace penumbra
