#pragma once
// The virtual shadow maps' page traffic under a scripted camera: the
// camera orbits its target about the vertical axis, a fixed angle a
// frame, and each frame's pages are read back (penumbra bench). With a
// static scene, after the first frame only the pages that came into view
// are rendered; the rest are cached.
#include <vector>

#include "render/renderer.hpp"

namespace penumbra {

struct VirtualOrbitFrame {
  int resident = 0;  // pages allocated after the frame
  int rendered = 0;  // pages drawn in it
  int pool_pages = 0;
  // Caster draws into pages in it (per-page culling), and what drawing
  // every caster draw into every rendered page would have been.
  int page_draws = 0;
  int unculled_page_draws = 0;
};

// `frames` frames, the first from the scene's camera, each next one turned
// `degrees` about the vertical through the camera's target. Restores the
// camera. Needs settings with --shadow-maps virtual.
std::vector<VirtualOrbitFrame> orbit_virtual_pages(Renderer& renderer, const RenderSettings& render,
                                                   const ShadowSettings& shadow, int frames,
                                                   float degrees);

}  // namespace penumbra
