#pragma once
// The depth maps of every shadow view (the views of all lights: see
// shadow/shadow_views.hpp), one layer of one depth-texture array each.
// The client draws its casters into each layer with a program of its own
// that writes the relative depth z-bar: penumbra's renderer its scene
// (render/scene_shadow_casters.hpp), an engine its meshes through
// ShadowMaps (include/penumbra/shadow_maps.hpp).
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "penumbra/gl/resources.hpp"

namespace penumbra {

class ShadowMapPass {
 public:
  // The depth maps' format.
  static constexpr GLenum kDepthFormat = GL_DEPTH_COMPONENT32F;

  // Draws every caster seen from shadow view `view` into the bound
  // framebuffer (the view's layer, cleared to 1), depth test LESS on.
  using DrawCasters = std::function<void(int view)>;

  // Calls draw(i) for views 0..view_count-1 with layer i bound (cleared
  // first), or with `stale` (one flag per view: ViewCache) only for the
  // views flagged; the other layers keep their depths. The array is
  // reallocated only when the view count or the size changes, and then
  // every view is drawn. Returns the number of views drawn.
  int execute(const DrawCasters& draw, int view_count, int map_size,
              std::span<const std::uint8_t> stale = {});

  // DEPTH_COMPONENT32F 2D array holding z-bar, one layer per view. Valid
  // after execute().
  [[nodiscard]] const gl::Texture& depth_maps() const { return maps_; }

 private:
  gl::Texture maps_;
  std::vector<gl::Framebuffer> framebuffers_;  // one per layer
};

}  // namespace penumbra
