#pragma once
// The depth maps of every shadow view (the views of all lights: see
// shadow/shadow_views.hpp), one layer of one depth-texture array each.
// The client draws its casters into each layer with a program of its own
// whose vertices are placed by shaders/shadow/caster_position.glsl: penumbra's
// renderer its scene (render/scene_shadow_casters.hpp), an engine its meshes
// through ShadowMaps (include/penumbra/shadow_maps.hpp).
//
// How each view's layer comes to hold z-bar without its casters writing
// gl_FragDepth (which would turn off early depth testing): an orthographic
// view's hardware depth is z-bar; a spot view's is the reversed z0 / z,
// drawn into a scratch layer and linearized into the view's layer by one
// full-screen pass; only a point light's faces (radial depth, RADIAL_DEPTH
// 1 in the caster shaders) write it.
//
// With more than one sample per texel (depth_samples()), the views are drawn
// into a multisampled array of the same layout (a spot view's scratch layer
// is multisampled too, and linearized sample by sample), which the moment
// resolves read (sampled_depth_maps()); depth_maps() then holds the nearest
// of each texel's samples (shaders/shadow/nearest_sample_depth.frag).
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/shared/gpu_types.h"

namespace penumbra {

// How a view's casters produce its depth (caster_position.glsl).
enum class CasterDepth {
  Relative,    // orthographic: the rasterizer's depth is z-bar (depth test LESS)
  Reciprocal,  // perspective: z0 / z, reversed (GREATER), linearized afterwards
  Written,     // radial: the fragments write z-bar (LESS; RADIAL_DEPTH 1)
};
[[nodiscard]] CasterDepth caster_depth(const gpu::GpuShadowView& view);

class ShadowMapPass {
 public:
  // The depth maps' format.
  static constexpr GLenum kDepthFormat = GL_DEPTH_COMPONENT32F;

  ShadowMapPass();

  // Draws every caster seen from shadow view `view` into the bound
  // framebuffer, with the program that suits caster_depth(views[view])
  // (RADIAL_DEPTH 1 for CasterDepth::Written) and the depth state set.
  using DrawCasters = std::function<void(int view)>;

  // Calls draw(i) for each view with its layer (or the scratch layer)
  // bound, clip control GL_ZERO_TO_ONE and depth range 0..1, or with
  // `stale` (one flag per view: ViewCache) only for the views flagged; the
  // other layers keep their depths. Restores clip control and depth range,
  // and leaves the depth test on, GL_LESS, writes on. At least one layer is
  // kept (cleared to 1) when there is no view. The array is reallocated
  // only when the view count or the size changes, and then every view is
  // drawn. Returns the number of views drawn.
  //
  // `samples` (1, 2, 4, 8: ShadowSettings::shadow_msaa) per texel; a
  // change of it draws every view again. Throws UsageError when the device
  // offers fewer (GL_MAX_DEPTH_TEXTURE_SAMPLES).
  //
  // `draw_second` (backprojection; one sample only): the second surfaces
  // of each view whose second_layer is set (second_layer(i,
  // views.size()): the array then has twice the layers), the nearest
  // surfaces facing the view's eye behind its first ones, drawn with the
  // first layers bound to UNIT_SHADOW_DEPTH by fragments that discard what
  // lies at or in front of their view's first layer (SECOND_SURFACES in
  // shaders/shadow/shadow_depth.frag), and back faces culled, so that a
  // closed caster's far side is skipped (triangles counter-clockwise seen
  // from outside, as OpenGL and glTF have them; a mesh wound the other way
  // gives its far side instead, which blocks no more than its near side
  // already does), where `stale` flags them. A caster hidden behind
  // another from the light's centre (the default scene's sphere under its
  // slab) hides parts of an area light's source from receivers that see
  // it through the source's edges (Bavoil, Callahan and Silva, "Robust
  // Soft Shadow Mapping with Backprojection and Depth Peeling", JGT 2008).
  int execute(const DrawCasters& draw, std::span<const gpu::GpuShadowView> views, int map_size,
              std::span<const std::uint8_t> stale = {}, int samples = 1,
              const DrawCasters& draw_second = {});

  // The layer of depth_maps() holding view `view`'s second surfaces when
  // execute() drew them for `view_count` views (GpuShadowView::second_layer).
  [[nodiscard]] static int second_layer(int view, int view_count) {
    return (view_count > 0 ? view_count : 1) + view;
  }

  // DEPTH_COMPONENT32F 2D array holding z-bar, one layer per view (with
  // samples > 1, the nearest of each texel's samples), then with second
  // surfaces one more per view. Valid after execute().
  [[nodiscard]] const gl::Texture& depth_maps() const { return maps_; }
  // What the moment resolves average: the multisampled array (read as a
  // sampler2DMSArray) when the last execute() had samples > 1, else
  // depth_maps().
  [[nodiscard]] const gl::Texture& sampled_depth_maps() const {
    return samples_ > 1 ? multisample_maps_ : maps_;
  }

 private:
  // Writes z-bar into `target` from the scratch layer's z0 / z (every
  // sample of it with samples > 1).
  void linearize(const gpu::GpuShadowView& view, GLuint target, int samples);
  // Writes the nearest sample of multisampled layer `layer` into the same
  // layer of depth_maps().
  void resolve_nearest(int layer);

  gl::Texture maps_;
  std::vector<gl::Framebuffer> framebuffers_;  // one per layer
  gl::Texture reciprocal_;                     // a spot view's z0 / z, one layer
  gl::Texture second_scratch_;  // a non-spot view's second surfaces, one layer (made on first use)
  gl::Framebuffer second_scratch_framebuffer_;
  gl::Framebuffer reciprocal_framebuffer_;
  gl::Program linearize_program_;
  gl::VertexArray empty_vertex_array_{"shadow linearize"};
  // samples > 1: the multisampled layers, their scratch layer, and the
  // programs that linearize and resolve them (made on first use).
  int samples_ = 1;  // of the last execute()
  gl::Texture multisample_maps_;
  std::vector<gl::Framebuffer> multisample_framebuffers_;
  gl::Texture multisample_reciprocal_;
  gl::Framebuffer multisample_reciprocal_framebuffer_;
  gl::Program multisample_linearize_program_;
  gl::Program nearest_sample_program_;
};

}  // namespace penumbra
