#pragma once
// ShadowMaps' contract with the engine's GL state (docs/library.md, "GL
// state"): what render() and bind() change is saved on entry and put back
// on exit, whatever the engine had set, and what the shadow passes depend
// on is set, not assumed. Dear ImGui's OpenGL backend keeps the same
// contract with its host (imgui_impl_opengl3.cpp, ImGui_ImplOpenGL3_RenderDrawData).
//
// Queries can stall a driver that runs ahead of the application (each
// glGet* waits for the commands before it on some), so the guard reads
// only what the frame's passes change: nothing on a frame whose maps are
// cached, the drawing state only when a view is drawn, the compute
// passes' bindings only when they run.
#include <epoxy/gl.h>

#include <array>
#include <span>
#include <vector>

namespace penumbra {

// What one render() changes.
struct GlStateScope {
  // The depth maps are drawn (ShadowMapPass and the caster callback): the
  // framebuffers, viewport 0, the vertex array, the rasterizer and depth
  // state (set_caster_pass_state) and the clip distances.
  bool caster_pass = false;
  // Units whose 2D-array texture and sampler a pass binds (every pass
  // binds 2D arrays only: the state test binds every target on every unit).
  std::span<const GLuint> texture_units;
  // Units whose 2D texture and sampler a pass binds (virtual maps' marking
  // reads the camera's depth buffer).
  std::span<const GLuint> texture_2d_units;
  std::span<const GLuint> image_units;
  std::span<const GLuint> uniform_buffers;  // indexed GL_UNIFORM_BUFFER bindings
  std::span<const GLuint> storage_buffers;  // indexed GL_SHADER_STORAGE_BUFFER bindings
};

// Saves, on construction, the state `scope` names (with the program, the
// active texture unit and the generic uniform- and storage-buffer
// bindings whenever it names anything); restores all of it on destruction
// (also when a caster callback throws). An empty scope reads and restores
// nothing.
class GlStateGuard {
 public:
  explicit GlStateGuard(const GlStateScope& scope);
  ~GlStateGuard();
  GlStateGuard(const GlStateGuard&) = delete;
  GlStateGuard& operator=(const GlStateGuard&) = delete;

  // The glGet* and glIsEnabled* calls the constructor made.
  [[nodiscard]] int queries() const { return queries_; }

 private:
  struct TextureUnit {
    GLenum target = GL_TEXTURE_2D_ARRAY;
    GLuint unit = 0;
    GLint texture = 0;  // bound to target
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
  // The drawing state, saved when the scope's caster_pass is set.
  struct CasterPass {
    GLint draw_framebuffer = 0, read_framebuffer = 0, vertex_array = 0;
    std::array<GLfloat, 4> viewport{};
    GLboolean depth_test = 0, cull_face = 0, scissor_test = 0, rasterizer_discard = 0;
    GLboolean polygon_offset_fill = 0, depth_clamp = 0, depth_mask = 0;
    GLint depth_func = 0;
    std::array<GLint, 2> polygon_mode{};
    std::array<GLboolean, 8> clip_distances{};
  };

  bool any_ = false;
  bool caster_pass_ = false;
  int queries_ = 0;
  GLint program_ = 0, active_texture_ = 0;
  GLint uniform_buffer_ = 0, storage_buffer_ = 0;
  CasterPass caster_{};
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

// Sets what drawing the casters into the depth maps depends on, for
// viewport 0 (the casters' vertex shader writes no gl_ViewportIndex):
// scissor test off there, rasterizer discard off, polygons filled, no
// culling (a closed caster seen from inside, a one-sided plane), no
// polygon offset or depth clamp (the shaders' biases are the only ones),
// clip distances 0-7 off (the casters' vertex shader writes none).
// ShadowMapPass sets the depth test, function, writes, the viewport, the
// clip control and the depth range, and restores the last two itself. The
// colour mask, blending, stencil test, sRGB writes, multisampling and
// alpha to coverage are left alone: the maps have no colour or stencil
// buffer and one sample, so none of them changes what is drawn.
void set_caster_pass_state();

}  // namespace penumbra
