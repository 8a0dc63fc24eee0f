#include "shadow/shadow_map_pass.hpp"

#include <string>

namespace penumbra {

ShadowMapPass::ShadowMapPass()
    : program_(gl::Program::graphics("shadow/shadow_depth.vert", "shadow/shadow_depth.frag")) {}

void ShadowMapPass::execute(const GpuScene& scene, int light_count, int map_size) {
  if (map_size != size_ || static_cast<int>(maps_.size()) != light_count) {
    maps_.clear();
    framebuffers_.clear();
    for (int i = 0; i < light_count; ++i) {
      std::string label = "shadow map " + std::to_string(i);
      maps_.emplace_back(gl::TextureInfo{
          .format = GL_DEPTH_COMPONENT32F, .width = map_size, .height = map_size, .label = label});
      gl::Framebuffer fb(label);
      fb.attach_depth(maps_.back());
      fb.set_draw_buffers(0);
      fb.check_complete();
      framebuffers_.push_back(std::move(fb));
    }
    size_ = map_size;
  }

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "shadow maps");
  program_.use();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glViewport(0, 0, map_size, map_size);
  const float far_depth = 1.0f;
  for (int i = 0; i < light_count; ++i) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[static_cast<std::size_t>(i)].id());
    glClearNamedFramebufferfv(framebuffers_[static_cast<std::size_t>(i)].id(), GL_DEPTH, 0,
                              &far_depth);
    glProgramUniform1i(program_.id(), 0, i);
    scene.draw();
  }
  glPopDebugGroup();
}

}  // namespace penumbra
