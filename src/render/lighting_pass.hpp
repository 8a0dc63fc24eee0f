#pragma once
// Full-screen deferred lighting into a 32-bit float target: the final
// linear colour, or one of the debug views.
#include <map>

#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/settings.hpp"
#include "render/gbuffer_pass.hpp"

namespace penumbra {

class LightingPass {
 public:
  LightingPass();

  // The frame, lights, shadow-views and shadow blocks must be bound.
  // `depth_maps` is the z-bar array of every shadow view (null when no
  // shadow was rendered); `filtered_maps` their filtered representations
  // (a summed-area-table array for the sat filter), or 0 for techniques
  // that read the depth maps. `ambient_occlusion` is the AO texture at the
  // G-buffer's size, read when the frame block's options.w is 1; 0 when
  // there is none.
  // `view` is the VIEW_* the frame block's options.y names: it picks the
  // program (LIGHTING_VIEWS).
  void execute(const GBufferPass& gbuffer, const gl::Texture* depth_maps, GLuint filtered_maps,
               const ShadowSettings& settings, int view, GLuint ambient_occlusion, int width,
               int height);

  // While `counts` (a GL_R32UI texture at the output's size) is not 0,
  // the techniques that counts_fetches() names run in a variant that adds
  // each pixel's texel reads to it (imageAtomicAdd,
  // shaders/shadow/fetch_count.glsl): `penumbra bench`'s fetches per
  // pixel. The normal frame writes nothing.
  void count_fetches(GLuint counts) { fetch_counts_ = counts; }
  // Whether count_fetches() counts the lookups of these settings: the two
  // soft shadows of the light's own source whose work varies per pixel,
  // PCSS and backprojection, through the light's own maps or its virtual
  // ones (whose every texel read is a page table's and a pool's).
  [[nodiscard]] static bool counts_fetches(const ShadowSettings& settings);

  // RGBA32F: rgb as the view defines, alpha 1 where geometry was seen.
  [[nodiscard]] const gl::Texture& output() const { return output_; }

  // RGBA32F: the shadow view (VIEW_SHADOW) of the frame block's chosen
  // light, which the lit image's pass writes as well (the second target);
  // valid while shadow_view_written().
  [[nodiscard]] const gl::Texture& shadow_output() const { return shadow_output_; }
  // Whether the last pass wrote shadow_output(): a pass of the final or the
  // shadow view (the other views' programs leave it undefined).
  [[nodiscard]] bool shadow_view_written() const { return shadow_view_written_; }

 private:
  // What tells one lighting program from another: its defines.
  struct ProgramKey {
    int technique = 0;  // TECHNIQUE_*
    int filter = 0;     // FILTER_*
    bool quantized_moments = false;
    bool soft = false;
    bool shadow_mips = false;
    bool count_fetches = false;
    bool virtual_maps = false;
    int views = 0;  // LIGHTING_VIEWS_*
    bool contact_shadows = false;
    bool accumulate_subframes = false;
    auto operator<=>(const ProgramKey&) const = default;
  };
  const gl::Program& program_for(const ShadowSettings& settings, int view);

  // One per combination of defines, compiled on first use.
  std::map<ProgramKey, gl::Program> programs_;
  GLuint fetch_counts_ = 0;
  gl::VertexArray empty_vao_;
  gl::Sampler nearest_;
  gl::Sampler bilinear_;
  // --shadow-mips: trilinear and anisotropic, one per --shadow-anisotropy.
  std::map<int, gl::Sampler> trilinear_;
  bool cpu_rasterizer_ = false;  // llvmpipe and the like (see execute())
  gl::Sampler compare_;
  gl::Texture output_;
  gl::Texture shadow_output_;
  bool shadow_view_written_ = false;
  // Bound as the AO texture where there is none (never read then): an
  // R32F texture at the output's size, as SSAO's output is. A software
  // rasterizer (llvmpipe) compiles a shader variant per bound textures'
  // format and size class; with nothing bound, each technique's lighting
  // shader would be compiled twice, once with AO and once without.
  gl::Texture unoccluded_;
  gl::Framebuffer framebuffer_;
  int width_ = 0, height_ = 0;
};

}  // namespace penumbra
