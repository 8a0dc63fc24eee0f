#include "render/present_pass.hpp"

#include <algorithm>

#include "penumbra/shared/bindings.h"

namespace penumbra {

PixelRect fit_rect(int source_width, int source_height, const PixelRect& target) {
  if (source_width <= 0 || source_height <= 0 || target.width <= 0 || target.height <= 0) {
    return {target.x, target.y, 0, 0};
  }
  // Compare aspect ratios in integers, so equal sizes fit exactly.
  const long long sw = source_width, sh = source_height;
  int width = target.width, height = target.height;
  if (sw * target.height > sh * target.width) {
    height = std::max(1, static_cast<int>(sh * target.width / sw));
  } else {
    width = std::max(1, static_cast<int>(sw * target.height / sh));
  }
  return {target.x + (target.width - width) / 2, target.y + (target.height - height) / 2, width,
          height};
}

PresentPass::PresentPass()
    : program_(gl::Program::graphics("common/fullscreen.vert", "render/present.frag")),
      empty_vao_("present"),
      nearest_(gl::SamplerInfo{
          .min_filter = GL_NEAREST, .mag_filter = GL_NEAREST, .label = "present nearest"}),
      bilinear_(gl::SamplerInfo{.label = "present bilinear"}) {}

void PresentPass::execute(const ViewSource& source, GLuint framebuffer, const PixelRect& target) {
  const gl::Texture& texture = *source.texture;
  const PixelRect rect = fit_rect(texture.width(), texture.height(), target);
  if (rect.width == 0 || rect.height == 0) return;
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "present");
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(rect.x, rect.y, rect.width, rect.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  // The encoding is applied here, not by the framebuffer.
  glDisable(GL_FRAMEBUFFER_SRGB);
  program_.use();
  glProgramUniform1i(program_.id(), 0, static_cast<GLint>(source.encoding));
  glProgramUniform1f(program_.id(), 1, source.log_scale);
  glProgramUniform1f(program_.id(), 2, source.log_offset);
  glBindTextureUnit(UNIT_PRESENT_SOURCE, texture.id());
  // One texel per pixel is shown as it is; a map scaled to the window is
  // filtered (a depth map without its comparison, which the sampler turns off).
  const bool one_to_one = rect.width == texture.width() && rect.height == texture.height();
  glBindSampler(UNIT_PRESENT_SOURCE, one_to_one ? nearest_.id() : bilinear_.id());
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(UNIT_PRESENT_SOURCE, 0);
  glPopDebugGroup();
}

}  // namespace penumbra
