#include "shadow/gl_state_guard.hpp"

namespace penumbra {

namespace {

void set_enabled(GLenum capability, GLboolean enabled) {
  if (enabled) {
    glEnable(capability);
  } else {
    glDisable(capability);
  }
}

// The first clip distances: every GL 4.5 device has at least 8
// (GL_MAX_CLIP_DISTANCES, OpenGL 4.5 table 23.59).
constexpr int kClipDistances = 8;

}  // namespace

GlStateGuard::GlStateGuard(const GlStateScope& scope)
    : any_(scope.caster_pass || !scope.texture_units.empty() || !scope.texture_2d_units.empty() ||
           !scope.image_units.empty() || !scope.uniform_buffers.empty() ||
           !scope.storage_buffers.empty()),
      caster_pass_(scope.caster_pass) {
  if (!any_) return;
  const auto get = [this](GLenum pname, GLint* value) {
    glGetIntegerv(pname, value);
    ++queries_;
  };
  const auto enabled = [this](GLenum capability) {
    ++queries_;
    return glIsEnabled(capability);
  };
  get(GL_CURRENT_PROGRAM, &program_);
  get(GL_ACTIVE_TEXTURE, &active_texture_);
  get(GL_UNIFORM_BUFFER_BINDING, &uniform_buffer_);
  get(GL_SHADER_STORAGE_BUFFER_BINDING, &storage_buffer_);
  if (caster_pass_) {
    CasterPass& c = caster_;
    get(GL_DRAW_FRAMEBUFFER_BINDING, &c.draw_framebuffer);
    get(GL_READ_FRAMEBUFFER_BINDING, &c.read_framebuffer);
    get(GL_VERTEX_ARRAY_BINDING, &c.vertex_array);
    glGetFloati_v(GL_VIEWPORT, 0, c.viewport.data());
    ++queries_;
    c.depth_test = enabled(GL_DEPTH_TEST);
    c.cull_face = enabled(GL_CULL_FACE);
    c.scissor_test = glIsEnabledi(GL_SCISSOR_TEST, 0);
    ++queries_;
    c.rasterizer_discard = enabled(GL_RASTERIZER_DISCARD);
    c.polygon_offset_fill = enabled(GL_POLYGON_OFFSET_FILL);
    c.depth_clamp = enabled(GL_DEPTH_CLAMP);
    get(GL_DEPTH_FUNC, &c.depth_func);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &c.depth_mask);
    ++queries_;
    get(GL_POLYGON_MODE, c.polygon_mode.data());
    for (int i = 0; i < kClipDistances; ++i) {
      c.clip_distances[static_cast<std::size_t>(i)] =
          enabled(GL_CLIP_DISTANCE0 + static_cast<GLenum>(i));
    }
  }

  // Per-unit texture bindings are read through the active unit.
  for (GLuint unit : scope.texture_units) {
    TextureUnit& saved = texture_units_.emplace_back();
    saved.unit = unit;
    glActiveTexture(GL_TEXTURE0 + unit);
    get(GL_TEXTURE_BINDING_2D_ARRAY, &saved.texture);
    get(GL_SAMPLER_BINDING, &saved.sampler);
  }
  for (GLuint unit : scope.texture_2d_units) {
    TextureUnit& saved = texture_units_.emplace_back();
    saved.target = GL_TEXTURE_2D;
    saved.unit = unit;
    glActiveTexture(GL_TEXTURE0 + unit);
    get(GL_TEXTURE_BINDING_2D, &saved.texture);
    get(GL_SAMPLER_BINDING, &saved.sampler);
  }
  if (!scope.texture_units.empty() || !scope.texture_2d_units.empty()) {
    glActiveTexture(static_cast<GLenum>(active_texture_));
  }
  for (GLuint unit : scope.image_units) {
    ImageUnit& saved = image_units_.emplace_back();
    saved.unit = unit;
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, unit, &saved.texture);
    glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, unit, &saved.level);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYERED, unit, &saved.layered);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, unit, &saved.layer);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, unit, &saved.access);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, unit, &saved.format);
    queries_ += 6;
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
      queries_ += 3;
    }
  };
  save_buffers(GL_UNIFORM_BUFFER, GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START,
               GL_UNIFORM_BUFFER_SIZE, scope.uniform_buffers);
  save_buffers(GL_SHADER_STORAGE_BUFFER, GL_SHADER_STORAGE_BUFFER_BINDING,
               GL_SHADER_STORAGE_BUFFER_START, GL_SHADER_STORAGE_BUFFER_SIZE,
               scope.storage_buffers);
}

GlStateGuard::~GlStateGuard() {
  if (!any_) return;
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
    glBindTexture(u.target, static_cast<GLuint>(u.texture));
    glBindSampler(u.unit, static_cast<GLuint>(u.sampler));
  }
  glActiveTexture(static_cast<GLenum>(active_texture_));
  // A program the engine deleted while it was current lived on only as
  // long as it stayed current: gone once the passes used theirs, it
  // leaves none to restore.
  const auto program = static_cast<GLuint>(program_);
  glUseProgram(program != 0 && glIsProgram(program) ? program : 0);
  if (!caster_pass_) return;

  const CasterPass& c = caster_;
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(c.draw_framebuffer));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(c.read_framebuffer));
  glBindVertexArray(static_cast<GLuint>(c.vertex_array));
  glViewportIndexedfv(0, c.viewport.data());
  set_enabled(GL_DEPTH_TEST, c.depth_test);
  set_enabled(GL_CULL_FACE, c.cull_face);
  if (c.scissor_test) {
    glEnablei(GL_SCISSOR_TEST, 0);
  } else {
    glDisablei(GL_SCISSOR_TEST, 0);
  }
  set_enabled(GL_RASTERIZER_DISCARD, c.rasterizer_discard);
  set_enabled(GL_POLYGON_OFFSET_FILL, c.polygon_offset_fill);
  set_enabled(GL_DEPTH_CLAMP, c.depth_clamp);
  glDepthFunc(static_cast<GLenum>(c.depth_func));
  glDepthMask(c.depth_mask);
  // Core profile: one mode for both faces (GL_POLYGON_MODE reports it twice).
  glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(c.polygon_mode[0]));
  for (int i = 0; i < kClipDistances; ++i) {
    set_enabled(GL_CLIP_DISTANCE0 + static_cast<GLenum>(i),
                c.clip_distances[static_cast<std::size_t>(i)]);
  }
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
  glDisablei(GL_SCISSOR_TEST, 0);
  glDisable(GL_RASTERIZER_DISCARD);
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_CLAMP);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  for (int i = 0; i < kClipDistances; ++i) glDisable(GL_CLIP_DISTANCE0 + static_cast<GLenum>(i));
}

}  // namespace penumbra
