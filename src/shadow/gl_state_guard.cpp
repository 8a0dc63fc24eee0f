#include "shadow/gl_state_guard.hpp"

namespace penumbra {

namespace {

// Every target a texture unit has a binding for (OpenGL 4.5, table 8.2).
constexpr std::array<std::pair<GLenum, GLenum>, 11> kTextureTargets{{
    {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D},
    {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D},
    {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D},
    {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY},
    {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY},
    {GL_TEXTURE_RECTANGLE, GL_TEXTURE_BINDING_RECTANGLE},
    {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP},
    {GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP_ARRAY},
    {GL_TEXTURE_BUFFER, GL_TEXTURE_BINDING_BUFFER},
    {GL_TEXTURE_2D_MULTISAMPLE, GL_TEXTURE_BINDING_2D_MULTISAMPLE},
    {GL_TEXTURE_2D_MULTISAMPLE_ARRAY, GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY},
}};

void set_enabled(GLenum capability, GLboolean enabled) {
  if (enabled) {
    glEnable(capability);
  } else {
    glDisable(capability);
  }
}

}  // namespace

GlStateGuard::GlStateGuard(const GlBindingPoints& points) {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_framebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_framebuffer_);
  glGetIntegerv(GL_VIEWPORT, viewport_.data());
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
  glGetIntegerv(GL_UNIFORM_BUFFER_BINDING, &uniform_buffer_);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &storage_buffer_);
  depth_test_ = glIsEnabled(GL_DEPTH_TEST);
  cull_face_ = glIsEnabled(GL_CULL_FACE);
  scissor_test_ = glIsEnabled(GL_SCISSOR_TEST);
  rasterizer_discard_ = glIsEnabled(GL_RASTERIZER_DISCARD);
  polygon_offset_fill_ = glIsEnabled(GL_POLYGON_OFFSET_FILL);
  depth_clamp_ = glIsEnabled(GL_DEPTH_CLAMP);
  glGetIntegerv(GL_DEPTH_FUNC, &depth_func_);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask_);
  glGetBooleanv(GL_COLOR_WRITEMASK, color_mask_.data());
  glGetIntegerv(GL_POLYGON_MODE, polygon_mode_.data());
  glGetIntegerv(GL_CLIP_ORIGIN, &clip_origin_);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &clip_depth_mode_);
  glGetDoublev(GL_DEPTH_RANGE, depth_range_.data());

  // Per-unit texture bindings are read through the active unit.
  for (GLuint unit : points.texture_units) {
    TextureUnit& saved = texture_units_.emplace_back();
    saved.unit = unit;
    glActiveTexture(GL_TEXTURE0 + unit);
    for (std::size_t t = 0; t < kTextureTargets.size(); ++t) {
      glGetIntegerv(kTextureTargets[t].second, &saved.textures[t]);
    }
    glGetIntegerv(GL_SAMPLER_BINDING, &saved.sampler);
  }
  glActiveTexture(static_cast<GLenum>(active_texture_));
  for (GLuint unit : points.image_units) {
    ImageUnit& saved = image_units_.emplace_back();
    saved.unit = unit;
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, unit, &saved.texture);
    glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, unit, &saved.level);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYERED, unit, &saved.layered);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, unit, &saved.layer);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, unit, &saved.access);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, unit, &saved.format);
  }
  const auto save_buffers = [&](GLenum target, GLenum binding, GLenum start, GLenum size,
                                std::span<const GLuint> indices) {
    for (GLuint index : indices) {
      BufferBinding& saved = buffers_.emplace_back();
      saved.target = target;
      saved.index = index;
      glGetIntegeri_v(binding, index, &saved.buffer);
      glGetInteger64i_v(start, index, &saved.start);
      glGetInteger64i_v(size, index, &saved.size);
    }
  };
  save_buffers(GL_UNIFORM_BUFFER, GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START,
               GL_UNIFORM_BUFFER_SIZE, points.uniform_buffers);
  save_buffers(GL_SHADER_STORAGE_BUFFER, GL_SHADER_STORAGE_BUFFER_BINDING,
               GL_SHADER_STORAGE_BUFFER_START, GL_SHADER_STORAGE_BUFFER_SIZE,
               points.storage_buffers);
}

GlStateGuard::~GlStateGuard() {
  // Indexed buffer bindings first: binding one also sets the generic
  // binding, restored after them.
  for (const BufferBinding& b : buffers_) {
    const auto buffer = static_cast<GLuint>(b.buffer);
    if (buffer != 0 && b.size > 0) {
      glBindBufferRange(b.target, b.index, buffer, static_cast<GLintptr>(b.start),
                        static_cast<GLsizeiptr>(b.size));
    } else {
      glBindBufferBase(b.target, b.index, buffer);
    }
  }
  glBindBuffer(GL_UNIFORM_BUFFER, static_cast<GLuint>(uniform_buffer_));
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(storage_buffer_));
  for (const ImageUnit& i : image_units_) {
    glBindImageTexture(i.unit, static_cast<GLuint>(i.texture), i.level,
                       static_cast<GLboolean>(i.layered), i.layer, static_cast<GLenum>(i.access),
                       static_cast<GLenum>(i.format));
  }
  for (const TextureUnit& u : texture_units_) {
    glActiveTexture(GL_TEXTURE0 + u.unit);
    for (std::size_t t = 0; t < kTextureTargets.size(); ++t) {
      glBindTexture(kTextureTargets[t].first, static_cast<GLuint>(u.textures[t]));
    }
    glBindSampler(u.unit, static_cast<GLuint>(u.sampler));
  }
  glActiveTexture(static_cast<GLenum>(active_texture_));

  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_framebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_framebuffer_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  // A program deleted while it was current is freed once another one is
  // used (OpenGL 4.5, 7.3): there is none to restore then.
  const auto program = static_cast<GLuint>(program_);
  glUseProgram(program != 0 && glIsProgram(program) ? program : 0);
  glBindVertexArray(static_cast<GLuint>(vertex_array_));
  set_enabled(GL_DEPTH_TEST, depth_test_);
  set_enabled(GL_CULL_FACE, cull_face_);
  set_enabled(GL_SCISSOR_TEST, scissor_test_);
  set_enabled(GL_RASTERIZER_DISCARD, rasterizer_discard_);
  set_enabled(GL_POLYGON_OFFSET_FILL, polygon_offset_fill_);
  set_enabled(GL_DEPTH_CLAMP, depth_clamp_);
  glDepthFunc(static_cast<GLenum>(depth_func_));
  glDepthMask(depth_mask_);
  glColorMask(color_mask_[0], color_mask_[1], color_mask_[2], color_mask_[3]);
  // Core profile: one mode for both faces (GL_POLYGON_MODE reports it twice).
  glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygon_mode_[0]));
  glClipControl(static_cast<GLenum>(clip_origin_), static_cast<GLenum>(clip_depth_mode_));
  glDepthRange(depth_range_[0], depth_range_[1]);
}

GenericBufferBindingsGuard::GenericBufferBindingsGuard() {
  glGetIntegerv(GL_UNIFORM_BUFFER_BINDING, &uniform_buffer_);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &storage_buffer_);
}

GenericBufferBindingsGuard::~GenericBufferBindingsGuard() {
  glBindBuffer(GL_UNIFORM_BUFFER, static_cast<GLuint>(uniform_buffer_));
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(storage_buffer_));
}

void set_caster_pass_state() {
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_RASTERIZER_DISCARD);
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_CLAMP);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glDepthRange(0.0, 1.0);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace penumbra
