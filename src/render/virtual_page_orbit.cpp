#include "render/virtual_page_orbit.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra {

std::vector<VirtualOrbitFrame> orbit_virtual_pages(Renderer& renderer, const RenderSettings& render,
                                                   const ShadowSettings& shadow, int frames,
                                                   float degrees) {
  const Camera start = renderer.scene().camera;
  std::vector<VirtualOrbitFrame> result;
  // The first frame renders every page it needs.
  renderer.forget_shadow_maps();
  for (int f = 0; f < frames; ++f) {
    Camera camera = start;
    const glm::mat4 turn =
        glm::rotate(glm::mat4(1.0f), glm::radians(degrees * static_cast<float>(f)),
                    glm::vec3(0.0f, 1.0f, 0.0f));
    camera.position =
        start.target + glm::vec3(turn * glm::vec4(start.position - start.target, 0.0f));
    renderer.set_camera(camera);
    renderer.render(render, shadow);
    const VirtualPageStats stats = renderer.virtual_page_stats();
    result.push_back({stats.resident, stats.rendered, stats.pool_pages, stats.page_draws,
                      stats.rendered * renderer.virtual_shadows().draw_count()});
  }
  renderer.set_camera(start);
  return result;
}

}  // namespace penumbra
