#include "penumbra/shadow/shadow_map_pass.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "penumbra/error.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

CasterDepth caster_depth(const gpu::GpuShadowView& view) {
  if (view.radial_depth != 0) return CasterDepth::Written;
  return view.perspective != 0 ? CasterDepth::Reciprocal : CasterDepth::Relative;
}

namespace {

// One framebuffer per layer of `maps`, its depth attachment that layer.
std::vector<gl::Framebuffer> layer_framebuffers(const gl::Texture& maps, const char* label) {
  std::vector<gl::Framebuffer> framebuffers;
  for (int i = 0; i < maps.layers(); ++i) {
    gl::Framebuffer fb(std::string(label) + " " + std::to_string(i));
    fb.attach_depth_layer(maps, i);
    fb.set_draw_buffers(0);
    fb.check_complete();
    framebuffers.push_back(std::move(fb));
  }
  return framebuffers;
}

}  // namespace

ShadowMapPass::ShadowMapPass()
    : linearize_program_(
          gl::Program::graphics("common/fullscreen.vert", "shadow/linearize_depth.frag")) {}

int ShadowMapPass::execute(const DrawCasters& draw, std::span<const gpu::GpuShadowView> views,
                           int map_size, std::span<const std::uint8_t> stale, int samples,
                           const DrawCasters& draw_second) {
  const bool second_surfaces = static_cast<bool>(draw_second);
  const int layers = std::max(static_cast<int>(views.size()), 1);
  const bool multisample = samples > 1;
  if (second_surfaces && multisample) {
    throw std::logic_error("a shadow map's second surfaces are drawn with one sample per texel");
  }
  // With second surfaces, layer layers + i holds view i's (second_layer()).
  const int array_layers = second_surfaces ? 2 * layers : layers;
  if (multisample) {
    GLint max_samples = 1;
    glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &max_samples);
    if (samples > max_samples) {
      throw UsageError("--shadow-msaa " + std::to_string(samples) +
                       " exceeds this GPU's limit of " + std::to_string(max_samples) +
                       " samples per depth texel");
    }
  }
  // Other samples than the last frame's: every layer is drawn again (the
  // nearest-sample maps of a multisampled frame are not a 1-sample frame's).
  bool all = stale.empty() || samples != samples_;
  samples_ = samples;
  if (gl::ensure_texture_array(maps_, kDepthFormat, map_size, map_size, array_layers,
                               "shadow maps")) {
    framebuffers_ = layer_framebuffers(maps_, "shadow view");
    all = true;  // a new array holds nothing yet
  }
  if (!multisample && multisample_maps_) {
    // Back to one sample: the multisampled layers (N times the maps'
    // memory) are not kept for a later frame.
    multisample_framebuffers_.clear();
    multisample_maps_ = gl::Texture();
    multisample_reciprocal_framebuffer_ = gl::Framebuffer();
    multisample_reciprocal_ = gl::Texture();
  }
  if (multisample &&
      gl::ensure_multisample_texture_array(multisample_maps_, kDepthFormat, map_size, map_size,
                                           layers, samples, "multisampled shadow maps")) {
    multisample_framebuffers_ = layer_framebuffers(multisample_maps_, "multisampled shadow view");
    all = true;
  }
  const bool any_reciprocal = std::any_of(views.begin(), views.end(), [](const auto& v) {
    return caster_depth(v) == CasterDepth::Reciprocal;
  });
  if (any_reciprocal && !multisample &&
      gl::ensure_texture_array(reciprocal_, kDepthFormat, map_size, map_size, 1,
                               "shadow reciprocal depth")) {
    reciprocal_framebuffer_ = std::move(layer_framebuffers(reciprocal_, "shadow reciprocal")[0]);
  }
  if (any_reciprocal && multisample &&
      gl::ensure_multisample_texture_array(multisample_reciprocal_, kDepthFormat, map_size,
                                           map_size, 1, samples,
                                           "multisampled shadow reciprocal depth")) {
    multisample_reciprocal_framebuffer_ =
        std::move(layer_framebuffers(multisample_reciprocal_, "multisampled shadow reciprocal")[0]);
  }
  if (multisample && !nearest_sample_program_) {
    multisample_linearize_program_ = gl::Program::graphics(
        "common/fullscreen.vert", "shadow/linearize_depth.frag", {{"MULTISAMPLE", "1"}});
    nearest_sample_program_ =
        gl::Program::graphics("common/fullscreen.vert", "shadow/nearest_sample_depth.frag");
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
  const GLboolean was_multisampling = glIsEnabled(GL_MULTISAMPLE);
  // Window depth = clip z / clip w exactly: z-bar for the orthographic
  // views (no remapping from [-1, 1], which would round near 0).
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  // Viewport 0's range and rectangle only: the casters write no
  // gl_ViewportIndex, and an engine's other viewports stay as they were.
  glDepthRangeIndexed(0, 0.0, 1.0);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  // Multisampled rasterization is on by default; an engine may have turned it off.
  if (multisample) glEnable(GL_MULTISAMPLE);
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(map_size), static_cast<float>(map_size));
  const float far_depth = 1.0f, reversed_far_depth = 0.0f;
  const std::vector<gl::Framebuffer>& targets =
      multisample ? multisample_framebuffers_ : framebuffers_;
  // Draws view i's casters (with `second`, its second surfaces) into
  // framebuffer `fb`.
  const auto draw_layer = [&](int i, GLuint fb, bool second) {
    const DrawCasters& casters = second ? draw_second : draw;
    if (i >= static_cast<int>(views.size())) {  // no view: an empty layer
      glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
    } else if (const gpu::GpuShadowView& view = views[static_cast<std::size_t>(i)];
               caster_depth(view) == CasterDepth::Reciprocal) {
      const GLuint scratch =
          multisample ? multisample_reciprocal_framebuffer_.id() : reciprocal_framebuffer_.id();
      glBindFramebuffer(GL_FRAMEBUFFER, scratch);
      glClearNamedFramebufferfv(scratch, GL_DEPTH, 0, &reversed_far_depth);
      glDepthFunc(GL_GREATER);
      casters(i);
      linearize(view, fb, samples);
    } else {
      glBindFramebuffer(GL_FRAMEBUFFER, fb);
      glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
      glDepthFunc(GL_LESS);
      casters(i);
    }
  };
  for (int i = 0; i < layers; ++i) {
    if (!is_stale(i)) continue;
    draw_layer(i, targets[static_cast<std::size_t>(i)].id(), false);
    if (multisample) resolve_nearest(i);
  }
  if (second_surfaces) {
    // The nearest surfaces facing the view's eye behind each layer's
    // (draw_second's fragments discard what lies at or in front of the
    // first layer, read from UNIT_SHADOW_DEPTH; the far sides facing away
    // are culled). Drawn into a scratch layer (a spot view's reciprocal
    // one, linearized into the array; else second_scratch_, copied), so
    // that no layer of the array is read while another is drawn.
    glBindTextureUnit(UNIT_SHADOW_DEPTH, maps_.id());
    glBindSampler(UNIT_SHADOW_DEPTH, 0);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    for (int i = 0; i < static_cast<int>(views.size()); ++i) {
      const gpu::GpuShadowView& view = views[static_cast<std::size_t>(i)];
      if (!is_stale(i) || view.second_layer == 0) continue;
      const GLuint target = framebuffers_[static_cast<std::size_t>(view.second_layer)].id();
      if (caster_depth(view) == CasterDepth::Reciprocal) {
        draw_layer(i, target, true);
        continue;
      }
      if (gl::ensure_texture_array(second_scratch_, kDepthFormat, map_size, map_size, 1,
                                   "shadow second surfaces")) {
        second_scratch_framebuffer_ =
            std::move(layer_framebuffers(second_scratch_, "shadow second surfaces")[0]);
      }
      draw_layer(i, second_scratch_framebuffer_.id(), true);
      glCopyImageSubData(second_scratch_.id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, maps_.id(),
                         GL_TEXTURE_2D_ARRAY, 0, 0, 0, view.second_layer, map_size, map_size, 1);
    }
    glDisable(GL_CULL_FACE);
  }
  glDepthFunc(GL_LESS);
  if (!was_multisampling) glDisable(GL_MULTISAMPLE);
  glClipControl(static_cast<GLenum>(clip_origin), static_cast<GLenum>(clip_depth));
  glDepthRangeIndexed(0, depth_range[0], depth_range[1]);
  glPopDebugGroup();
  return drawn;
}

void ShadowMapPass::linearize(const gpu::GpuShadowView& view, GLuint target, int samples) {
  GLint vertex_array = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array);
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glDepthFunc(GL_ALWAYS);
  const gl::Program& program = samples > 1 ? multisample_linearize_program_ : linearize_program_;
  glProgramUniform2f(program.id(), 0, view.depth_range.x, view.depth_range.y);
  program.use();
  glBindTextureUnit(0, samples > 1 ? multisample_reciprocal_.id() : reciprocal_.id());
  glBindSampler(0, 0);
  glBindVertexArray(empty_vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(static_cast<GLuint>(vertex_array));
}

void ShadowMapPass::resolve_nearest(int layer) {
  GLint vertex_array = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[static_cast<std::size_t>(layer)].id());
  glDepthFunc(GL_ALWAYS);
  glProgramUniform1i(nearest_sample_program_.id(), 0, layer);
  nearest_sample_program_.use();
  glBindTextureUnit(0, multisample_maps_.id());
  glBindSampler(0, 0);
  glBindVertexArray(empty_vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(static_cast<GLuint>(vertex_array));
}

}  // namespace penumbra
