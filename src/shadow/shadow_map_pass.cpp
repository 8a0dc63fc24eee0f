#include "penumbra/shadow/shadow_map_pass.hpp"

#include <algorithm>
#include <string>

namespace penumbra {

CasterDepth caster_depth(const gpu::GpuShadowView& view) {
  if (view.radial_depth != 0) return CasterDepth::Written;
  return view.perspective != 0 ? CasterDepth::Reciprocal : CasterDepth::Relative;
}

ShadowMapPass::ShadowMapPass()
    : linearize_program_(
          gl::Program::graphics("common/fullscreen.vert", "shadow/linearize_depth.frag")) {}

int ShadowMapPass::execute(const DrawCasters& draw, std::span<const gpu::GpuShadowView> views,
                           int map_size, std::span<const std::uint8_t> stale) {
  const int layers = std::max(static_cast<int>(views.size()), 1);
  bool all = stale.empty();
  if (gl::ensure_texture_array(maps_, kDepthFormat, map_size, map_size, layers, "shadow maps")) {
    framebuffers_.clear();
    for (int i = 0; i < layers; ++i) {
      gl::Framebuffer fb("shadow view " + std::to_string(i));
      fb.attach_depth_layer(maps_, i);
      fb.set_draw_buffers(0);
      fb.check_complete();
      framebuffers_.push_back(std::move(fb));
    }
    all = true;  // a new array holds nothing yet
  }
  const bool any_reciprocal = std::any_of(views.begin(), views.end(), [](const auto& v) {
    return caster_depth(v) == CasterDepth::Reciprocal;
  });
  if (any_reciprocal && gl::ensure_texture_array(reciprocal_, kDepthFormat, map_size, map_size, 1,
                                                 "shadow reciprocal depth")) {
    reciprocal_framebuffer_ = gl::Framebuffer("shadow reciprocal depth");
    reciprocal_framebuffer_.attach_depth_layer(reciprocal_, 0);
    reciprocal_framebuffer_.set_draw_buffers(0);
    reciprocal_framebuffer_.check_complete();
  }
  // A layer is drawn when the cache flags its view (every layer without
  // flags, or in a new array, which holds nothing yet).
  const auto is_stale = [&](int i) {
    return all || static_cast<std::size_t>(i) >= stale.size() ||
           stale[static_cast<std::size_t>(i)] != 0;
  };
  int drawn = 0;
  for (int i = 0; i < static_cast<int>(views.size()); ++i) drawn += is_stale(i) ? 1 : 0;
  if (drawn == 0 && !all) return 0;

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "shadow maps");
  GLint clip_origin = GL_LOWER_LEFT, clip_depth = GL_NEGATIVE_ONE_TO_ONE;
  GLdouble depth_range[2] = {0.0, 1.0};
  glGetIntegerv(GL_CLIP_ORIGIN, &clip_origin);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &clip_depth);
  glGetDoublei_v(GL_DEPTH_RANGE, 0, depth_range);
  // Window depth = clip z / clip w exactly: z-bar for the orthographic
  // views (no remapping from [-1, 1], which would round near 0).
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  // Viewport 0's range and rectangle only: the casters write no
  // gl_ViewportIndex, and an engine's other viewports stay as they were.
  glDepthRangeIndexed(0, 0.0, 1.0);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(map_size), static_cast<float>(map_size));
  const float far_depth = 1.0f, reversed_far_depth = 0.0f;
  for (int i = 0; i < layers; ++i) {
    if (!is_stale(i)) continue;
    const GLuint fb = framebuffers_[static_cast<std::size_t>(i)].id();
    if (i >= static_cast<int>(views.size())) {  // no view: an empty layer
      glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
      continue;
    }
    const gpu::GpuShadowView& view = views[static_cast<std::size_t>(i)];
    if (caster_depth(view) == CasterDepth::Reciprocal) {
      const GLuint scratch = reciprocal_framebuffer_.id();
      glBindFramebuffer(GL_FRAMEBUFFER, scratch);
      glClearNamedFramebufferfv(scratch, GL_DEPTH, 0, &reversed_far_depth);
      glDepthFunc(GL_GREATER);
      draw(i);
      linearize(view, fb);
    } else {
      glBindFramebuffer(GL_FRAMEBUFFER, fb);
      glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
      glDepthFunc(GL_LESS);
      draw(i);
    }
  }
  glDepthFunc(GL_LESS);
  glClipControl(static_cast<GLenum>(clip_origin), static_cast<GLenum>(clip_depth));
  glDepthRangeIndexed(0, depth_range[0], depth_range[1]);
  glPopDebugGroup();
  return drawn;
}

void ShadowMapPass::linearize(const gpu::GpuShadowView& view, GLuint target) {
  GLint vertex_array = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array);
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glDepthFunc(GL_ALWAYS);
  const GLuint program = linearize_program_.id();
  glProgramUniform2f(program, 0, view.depth_range.x, view.depth_range.y);
  linearize_program_.use();
  glBindTextureUnit(0, reciprocal_.id());
  glBindSampler(0, 0);
  glBindVertexArray(empty_vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(static_cast<GLuint>(vertex_array));
}

}  // namespace penumbra
