#include "penumbra/shadow/shadow_map_pass.hpp"

#include <string>

namespace penumbra {

int ShadowMapPass::execute(const DrawCasters& draw, int view_count, int map_size,
                           std::span<const std::uint8_t> stale) {
  bool all = stale.empty();
  if (gl::ensure_texture_array(maps_, kDepthFormat, map_size, map_size, view_count,
                               "shadow maps")) {
    framebuffers_.clear();
    for (int i = 0; i < view_count; ++i) {
      gl::Framebuffer fb("shadow view " + std::to_string(i));
      fb.attach_depth_layer(maps_, i);
      fb.set_draw_buffers(0);
      fb.check_complete();
      framebuffers_.push_back(std::move(fb));
    }
    all = true;  // a new array holds nothing yet
  }
  int drawn = 0;
  for (int i = 0; i < view_count && !all; ++i) drawn += stale[static_cast<std::size_t>(i)] != 0;
  if (all) drawn = view_count;
  if (drawn == 0) return 0;

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "shadow maps");
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glViewport(0, 0, map_size, map_size);
  const float far_depth = 1.0f;
  for (int i = 0; i < view_count; ++i) {
    if (!all && stale[static_cast<std::size_t>(i)] == 0) continue;
    const GLuint fb = framebuffers_[static_cast<std::size_t>(i)].id();
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
    draw(i);
  }
  glPopDebugGroup();
  return drawn;
}

}  // namespace penumbra
