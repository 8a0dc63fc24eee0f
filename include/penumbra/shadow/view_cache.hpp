#pragma once
// Cached shadow maps: which shadow views must be drawn again this frame.
// A view's depth map depends only on its view (matrices and depth range),
// the map size and the casters it sees, so a view is drawn again only when
// one of these changed; every other layer keeps last frame's depths. A
// static frame draws no view and runs no resolve or filter pass.
//
// The whole view is drawn again when one caster it sees moved (not the
// engines' split of static casters cached in a copy and dynamic ones drawn
// over it each frame): a moved caster costs its views one depth pass, a
// static frame costs nothing, and no copy of the maps exists (docs/
// library.md, "Casters and caching", measures both).
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "penumbra/position_span.hpp"
#include "penumbra/shadow_block.hpp"

namespace penumbra {

// Whether any part of `box` may project inside the view: false only when
// all eight corners lie behind the eye (w <= 0) or outside one of the
// x or y clip planes (conservative; depth is not tested, so casters in
// front of a view's near plane still count).
[[nodiscard]] bool box_may_be_seen(const glm::mat4& view_projection, const CasterBounds& box);

class ViewCache {
 public:
  // Every view is drawn again at the next stale_views().
  void invalidate() { all_stale_ = true; }
  // A caster moved (or changed) from `before` to `after`: the views that
  // see either box are drawn again at the next stale_views().
  void caster_moved(const CasterBounds& before, const CasterBounds& after);

  // One flag per view (1: draw it), for this frame's views in a map of
  // map_size texels: those whose view differs from the one last drawn into
  // their layer, or that see a moved caster; all of them after
  // invalidate() or when the count or the size changed. Records the views
  // as drawn and forgets the moved casters. The flags are the cache's own
  // (no allocation per frame), valid until the next call.
  [[nodiscard]] std::span<const std::uint8_t> stale_views(std::span<const ShadowViewData> views,
                                                          int map_size);

 private:
  std::vector<ShadowViewData> drawn_;  // the view each layer holds
  int map_size_ = 0;
  bool all_stale_ = true;
  std::vector<CasterBounds> moved_;  // the boxes before and after each move
  std::vector<std::uint8_t> stale_;  // stale_views()' flags
};

}  // namespace penumbra
