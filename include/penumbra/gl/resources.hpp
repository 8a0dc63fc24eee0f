#pragma once
// RAII wrappers over OpenGL 4.5 objects, created with direct state access.
#include <epoxy/gl.h>

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "penumbra/gl/handle.hpp"

namespace penumbra::gl {

namespace detail {
inline void delete_buffer(GLuint id) {
  glDeleteBuffers(1, &id);
}
inline void delete_texture(GLuint id) {
  glDeleteTextures(1, &id);
}
inline void delete_framebuffer(GLuint id) {
  glDeleteFramebuffers(1, &id);
}
inline void delete_sampler(GLuint id) {
  glDeleteSamplers(1, &id);
}
inline void delete_vertex_array(GLuint id) {
  glDeleteVertexArrays(1, &id);
}
}  // namespace detail

// Names the object in debug output and GPU captures.
void set_label(GLenum identifier, GLuint id, std::string_view label);

class Buffer {
 public:
  Buffer() = default;
  // Immutable storage of `size` bytes; `data` may be empty. Dynamic buffers
  // can be rewritten with update().
  Buffer(std::size_t size, const void* data, bool dynamic, std::string_view label);
  template <class T>
  static Buffer from(std::span<const T> values, std::string_view label) {
    return Buffer(values.size_bytes(), values.data(), false, label);
  }

  void update(const void* data, std::size_t size, std::size_t offset = 0);
  [[nodiscard]] GLuint id() const { return handle_.id(); }
  [[nodiscard]] std::size_t size() const { return size_; }

 private:
  Handle<detail::delete_buffer> handle_;
  std::size_t size_ = 0;
};

struct TextureInfo {
  GLenum target = GL_TEXTURE_2D;
  GLenum format = GL_RGBA8;  // sized internal format
  int width = 1;
  int height = 1;
  int layers = 1;   // array layers, or 6 faces for cube maps
  int levels = 1;   // mip levels
  int samples = 1;  // > 1 for multisampled targets: the least the texture gets
  std::string_view label;
};

class Texture {
 public:
  Texture() = default;
  explicit Texture(const TextureInfo& info);

  [[nodiscard]] GLuint id() const { return handle_.id(); }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] int layers() const { return layers_; }
  [[nodiscard]] int levels() const { return levels_; }
  [[nodiscard]] GLenum format() const { return format_; }
  // Samples per texel: what the driver allocated, which may be more than
  // TextureInfo::samples asked for (llvmpipe gives 4 for 2).
  [[nodiscard]] int samples() const { return samples_; }
  [[nodiscard]] int requested_samples() const { return requested_samples_; }
  [[nodiscard]] explicit operator bool() const { return static_cast<bool>(handle_); }

 private:
  Handle<detail::delete_texture> handle_;
  int width_ = 0;
  int height_ = 0;
  int layers_ = 0;
  int levels_ = 0;
  GLenum format_ = 0;
  int samples_ = 1;
  int requested_samples_ = 1;
};

// Makes `texture` a 2D array texture of this format, size, layer count and
// number of mip levels, reallocating it only when it is not one already,
// so passes keep their textures from frame to frame. True when it was
// (re)allocated.
bool ensure_texture_array(Texture& texture, GLenum format, int width, int height, int layers,
                          std::string_view label, int levels = 1);

// The same for a multisampled 2D array texture of at least `samples`
// samples per texel (fixed sample locations), reallocated when another
// count is asked for.
bool ensure_multisample_texture_array(Texture& texture, GLenum format, int width, int height,
                                      int layers, int samples, std::string_view label);

class Framebuffer {
 public:
  Framebuffer() = default;
  explicit Framebuffer(std::string_view label);

  void attach_color(int index, const Texture& texture, int level = 0);
  void attach_depth(const Texture& texture, int level = 0);
  // One layer of an array texture as the depth attachment.
  void attach_depth_layer(const Texture& texture, int layer, int level = 0);
  // Selects which color attachments fragment outputs 0..n-1 write to.
  void set_draw_buffers(int count);
  // Throws RuntimeError naming the framebuffer if it is incomplete.
  void check_complete() const;
  [[nodiscard]] GLuint id() const { return handle_.id(); }

 private:
  Handle<detail::delete_framebuffer> handle_;
  std::string label_;
};

struct SamplerInfo {
  GLenum min_filter = GL_LINEAR;
  GLenum mag_filter = GL_LINEAR;
  GLenum wrap = GL_CLAMP_TO_EDGE;
  GLenum compare_mode = GL_NONE;  // GL_COMPARE_REF_TO_TEXTURE for sampler2DShadow
  // GL_TEXTURE_MAX_ANISOTROPY, clamped to the device's maximum; 1: off.
  float max_anisotropy = 1.0f;
  std::string_view label;
};

class Sampler {
 public:
  Sampler() = default;
  explicit Sampler(const SamplerInfo& info);
  [[nodiscard]] GLuint id() const { return handle_.id(); }

 private:
  Handle<detail::delete_sampler> handle_;
};

class VertexArray {
 public:
  VertexArray() = default;
  explicit VertexArray(std::string_view label);
  [[nodiscard]] GLuint id() const { return handle_.id(); }

 private:
  Handle<detail::delete_vertex_array> handle_;
};

}  // namespace penumbra::gl
