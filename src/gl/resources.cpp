#include "penumbra/gl/resources.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "penumbra/error.hpp"

namespace penumbra::gl {

void set_label(GLenum identifier, GLuint id, std::string_view label) {
  if (!label.empty()) {
    glObjectLabel(identifier, id, static_cast<GLsizei>(label.size()), label.data());
  }
}

Buffer::Buffer(std::size_t size, const void* data, bool dynamic, std::string_view label)
    : size_(size) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  handle_ = Handle<detail::delete_buffer>(id);
  // A zero-sized store is invalid; keep one byte so empty scenes still bind.
  glNamedBufferStorage(id, static_cast<GLsizeiptr>(size == 0 ? 1 : size),
                       size == 0 ? nullptr : data, dynamic ? GL_DYNAMIC_STORAGE_BIT : 0);
  set_label(GL_BUFFER, id, label);
}

void Buffer::update(const void* data, std::size_t size, std::size_t offset) {
  glNamedBufferSubData(handle_.id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(size),
                       data);
}

bool ensure_texture_array(Texture& texture, GLenum format, int width, int height, int layers,
                          std::string_view label, int levels) {
  if (texture && texture.width() == width && texture.height() == height &&
      texture.layers() == layers && texture.format() == format && texture.levels() == levels) {
    return false;
  }
  texture = Texture(TextureInfo{.target = GL_TEXTURE_2D_ARRAY,
                                .format = format,
                                .width = width,
                                .height = height,
                                .layers = layers,
                                .levels = levels,
                                .label = label});
  return true;
}

bool ensure_multisample_texture_array(Texture& texture, GLenum format, int width, int height,
                                      int layers, int samples, std::string_view label) {
  if (texture && texture.width() == width && texture.height() == height &&
      texture.layers() == layers && texture.format() == format &&
      texture.requested_samples() == samples) {
    return false;
  }
  texture = Texture(TextureInfo{.target = GL_TEXTURE_2D_MULTISAMPLE_ARRAY,
                                .format = format,
                                .width = width,
                                .height = height,
                                .layers = layers,
                                .samples = samples,
                                .label = label});
  return true;
}

Texture::Texture(const TextureInfo& info)
    : width_(info.width),
      height_(info.height),
      layers_(info.layers),
      levels_(info.levels),
      format_(info.format),
      samples_(info.samples),
      requested_samples_(info.samples) {
  GLuint id = 0;
  glCreateTextures(info.target, 1, &id);
  handle_ = Handle<detail::delete_texture>(id);
  switch (info.target) {
    case GL_TEXTURE_2D:
    case GL_TEXTURE_CUBE_MAP:
      glTextureStorage2D(id, info.levels, info.format, info.width, info.height);
      break;
    case GL_TEXTURE_2D_ARRAY:
    case GL_TEXTURE_CUBE_MAP_ARRAY:
      glTextureStorage3D(id, info.levels, info.format, info.width, info.height, info.layers);
      break;
    case GL_TEXTURE_2D_MULTISAMPLE:
      glTextureStorage2DMultisample(id, info.samples, info.format, info.width, info.height,
                                    GL_TRUE);
      break;
    case GL_TEXTURE_2D_MULTISAMPLE_ARRAY:
      glTextureStorage3DMultisample(id, info.samples, info.format, info.width, info.height,
                                    info.layers, GL_TRUE);
      break;
    default:
      throw RuntimeError("unsupported texture target");
  }
  if (info.target == GL_TEXTURE_2D_MULTISAMPLE || info.target == GL_TEXTURE_2D_MULTISAMPLE_ARRAY) {
    // The count asked for is a minimum (the driver may give more: llvmpipe
    // gives 4 for 2); shaders that loop over the samples use the real one.
    GLint samples = info.samples;
    glGetTextureLevelParameteriv(id, 0, GL_TEXTURE_SAMPLES, &samples);
    samples_ = std::max(static_cast<int>(samples), 1);
  }
  // Filter with NEAREST unless a sampler says otherwise: the default
  // (NEAREST_MIPMAP_LINEAR) makes integer textures incomplete, and then even
  // texelFetch reads zeros.
  if (info.target != GL_TEXTURE_2D_MULTISAMPLE && info.target != GL_TEXTURE_2D_MULTISAMPLE_ARRAY) {
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  set_label(GL_TEXTURE, id, info.label);
}

Framebuffer::Framebuffer(std::string_view label) : label_(label) {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  handle_ = Handle<detail::delete_framebuffer>(id);
  set_label(GL_FRAMEBUFFER, id, label);
}

void Framebuffer::attach_color(int index, const Texture& texture, int level) {
  glNamedFramebufferTexture(handle_.id(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index),
                            texture.id(), level);
}

void Framebuffer::attach_depth(const Texture& texture, int level) {
  glNamedFramebufferTexture(handle_.id(), GL_DEPTH_ATTACHMENT, texture.id(), level);
}

void Framebuffer::attach_depth_layer(const Texture& texture, int layer, int level) {
  glNamedFramebufferTextureLayer(handle_.id(), GL_DEPTH_ATTACHMENT, texture.id(), level, layer);
}

void Framebuffer::set_draw_buffers(int count) {
  GLenum buffers[8];
  for (int i = 0; i < count && i < 8; ++i)
    buffers[i] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
  if (count == 0) {
    glNamedFramebufferDrawBuffer(handle_.id(), GL_NONE);
  } else {
    glNamedFramebufferDrawBuffers(handle_.id(), count, buffers);
  }
}

void Framebuffer::check_complete() const {
  GLenum status = glCheckNamedFramebufferStatus(handle_.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE && glGetError() == GL_OUT_OF_MEMORY) {
    // Its textures could not be allocated: say so, not the status it left.
    throw RuntimeError("out of GPU memory for the framebuffer '" + label_ +
                       "' (a smaller --width, --height or --shadow-map-size may fit)");
  }
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw RuntimeError("framebuffer '" + label_ + "' is incomplete (status 0x" + [&] {
      char hex[16];
      std::snprintf(hex, sizeof hex, "%x", status);
      return std::string(hex);
    }() + ")");
  }
}

Sampler::Sampler(const SamplerInfo& info) {
  GLuint id = 0;
  glCreateSamplers(1, &id);
  handle_ = Handle<detail::delete_sampler>(id);
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(info.min_filter));
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(info.mag_filter));
  glSamplerParameteri(id, GL_TEXTURE_WRAP_S, static_cast<GLint>(info.wrap));
  glSamplerParameteri(id, GL_TEXTURE_WRAP_T, static_cast<GLint>(info.wrap));
  glSamplerParameteri(id, GL_TEXTURE_WRAP_R, static_cast<GLint>(info.wrap));
  if (info.compare_mode != GL_NONE) {
    glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, static_cast<GLint>(info.compare_mode));
    glSamplerParameteri(id, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  }
  // Anisotropic filtering is core in OpenGL 4.6 and an extension (ARB or
  // EXT, the same enums) before; where none has it, sampling stays isotropic.
  if (info.max_anisotropy > 1.0f &&
      (epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic") ||
       epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic"))) {
    GLfloat largest = 1.0f;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &largest);
    glSamplerParameterf(id, GL_TEXTURE_MAX_ANISOTROPY, std::min(info.max_anisotropy, largest));
  }
  set_label(GL_SAMPLER, id, info.label);
}

VertexArray::VertexArray(std::string_view label) {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  handle_ = Handle<detail::delete_vertex_array>(id);
  set_label(GL_VERTEX_ARRAY, id, label);
}

}  // namespace penumbra::gl
