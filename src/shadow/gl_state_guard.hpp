#pragma once
// ShadowMaps' contract with the engine's GL state (docs/library.md, "GL
// state"): what render() and bind() change is saved on entry and put back
// on exit, whatever the engine had set, and what the shadow passes depend
// on is set, not assumed. Dear ImGui's OpenGL backend keeps the same
// contract with its host (imgui_impl_opengl3.cpp, ImGui_ImplOpenGL3_RenderDrawData).
#include <epoxy/gl.h>

#include <array>
#include <span>
#include <vector>

namespace penumbra {

// The indexed bindings a pass changes, besides the fixed state below.
struct GlBindingPoints {
  std::span<const GLuint> texture_units;  // every texture target and the sampler
  std::span<const GLuint> image_units;
  std::span<const GLuint> uniform_buffers;  // indexed GL_UNIFORM_BUFFER bindings
  std::span<const GLuint> storage_buffers;  // indexed GL_SHADER_STORAGE_BUFFER bindings
};

// Saves, on construction, the state the shadow passes change: both
// framebuffer bindings, the viewport, the program, the vertex array, the
// active texture unit, the generic uniform- and storage-buffer bindings,
// the depth, cull, scissor, rasterizer-discard, polygon-offset, depth-clamp,
// colour-mask, polygon-mode, clip-control and depth-range state, and
// `points`; restores all of it on destruction (also when a caster callback
// throws).
class GlStateGuard {
 public:
  explicit GlStateGuard(const GlBindingPoints& points);
  ~GlStateGuard();
  GlStateGuard(const GlStateGuard&) = delete;
  GlStateGuard& operator=(const GlStateGuard&) = delete;

 private:
  struct TextureUnit {
    GLuint unit = 0;
    std::array<GLint, 11> textures{};  // one per target of kTextureTargets
    GLint sampler = 0;
  };
  struct ImageUnit {
    GLuint unit = 0;
    GLint texture = 0, level = 0, layered = 0, layer = 0, access = 0, format = 0;
  };
  struct BufferBinding {
    GLenum target = 0;
    GLuint index = 0;
    GLint buffer = 0;
    GLint64 start = 0, size = 0;
  };

  GLint draw_framebuffer_ = 0, read_framebuffer_ = 0;
  std::array<GLint, 4> viewport_{};
  GLint program_ = 0, vertex_array_ = 0, active_texture_ = 0;
  GLint uniform_buffer_ = 0, storage_buffer_ = 0;
  GLboolean depth_test_ = 0, cull_face_ = 0, scissor_test_ = 0, rasterizer_discard_ = 0;
  GLboolean polygon_offset_fill_ = 0, depth_clamp_ = 0;
  GLint depth_func_ = 0;
  GLboolean depth_mask_ = 0;
  std::array<GLboolean, 4> color_mask_{};
  std::array<GLint, 2> polygon_mode_{};
  GLint clip_origin_ = 0, clip_depth_mode_ = 0;
  std::array<GLdouble, 2> depth_range_{};
  std::vector<TextureUnit> texture_units_;
  std::vector<ImageUnit> image_units_;
  std::vector<BufferBinding> buffers_;
};

// Saves the generic GL_UNIFORM_BUFFER and GL_SHADER_STORAGE_BUFFER
// bindings, which glBindBufferBase moves along with the indexed ones, and
// restores them on destruction: bind() leaves its indexed bindings bound,
// and nothing else.
class GenericBufferBindingsGuard {
 public:
  GenericBufferBindingsGuard();
  ~GenericBufferBindingsGuard();
  GenericBufferBindingsGuard(const GenericBufferBindingsGuard&) = delete;
  GenericBufferBindingsGuard& operator=(const GenericBufferBindingsGuard&) = delete;

 private:
  GLint uniform_buffer_ = 0, storage_buffer_ = 0;
};

// Sets what drawing the casters into the depth maps depends on: scissor
// and rasterizer discard off, polygons filled, no culling (a closed caster
// seen from inside, a one-sided plane), no polygon offset or depth clamp
// (the shaders' biases are the only ones), clip control lower-left and
// -1..1 with depth range 0..1 (the views' projections assume OpenGL's
// conventions), colour writes on (the maps have no colour attachment; a
// caster callback that adds one sees them on). ShadowMapPass sets the
// depth test, function, writes and the viewport.
void set_caster_pass_state();

}  // namespace penumbra
