#pragma once
// Virtual shadow maps for a list of lights (docs/rendering.md, "Virtual
// shadow maps"): a directional light's clipmap, a spot light's mip levels,
// their pages in one pool and their levels' entries in one page table (a
// layer per level). Each frame, marks the pages the camera's pixels read
// under each level bias (a compute pass over the camera's depth buffer),
// keeps the finest bias whose pages fit the pool, allocates pool pages for
// the new ones and frees the unrequested ones (compute, with a free list
// and atomic counters), and culls the client's caster draws per page
// (compute: a draw is listed for a page only where its world bounds cover
// the page's square). Pages stay cached while they are requested and
// nothing over them moved. The client then draws its casters into the
// listed pages, two lists (the orthographic levels' pages and the
// perspective levels'): penumbra's renderer with indirect instanced draws
// (one instance per page its draw covers: commands(), draws_offset()),
// ShadowMaps page by page through the engine's callback (read_render_list()).
// Nothing is read back in update(): read_stats() and read_page_draws() are
// for benchmarks and tests.
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "penumbra/camera_depth_buffer.hpp"
#include "penumbra/gl/gpu_profiler.hpp"
#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/caster_bounds.hpp"
#include "penumbra/shadow/virtual_clipmap.hpp"
#include "penumbra/shared/gpu_types.h"

namespace penumbra {

// What the last frames did with the pages (read back from the GPU).
struct VirtualPageStats {
  int pool_pages = 0;  // the pool's size
  int resident = 0;    // pages holding depths (allocated)
  int rendered = 0;    // pages drawn by the last update()
  int unserved = 0;    // requested pages the pool had no room for in the last update()
  // Pages x draws of the last update(): instances the caster draws drew
  // (without culling, rendered x the number of draws).
  int page_draws = 0;
  // The level bias of the last update(): half levels finer than one
  // texel per pixel, the finest whose pages fit the pool.
  int bias = 0;
};

// One light's virtual maps in a frame: light `light_index` (an index into
// the lights the lookup's block holds), its clipmap (directional) or mip
// levels (spot), fitted to the frame's camera.
struct VirtualLightMaps {
  int light_index = -1;
  Light light;
  VirtualClipmap maps;
};

// Where bind() puts what the lookup reads (virtual_shadow.glsl).
struct VirtualBindings {
  GLuint block = BINDING_VIRTUAL_UBO;  // GpuVirtualShadow, std140
  GLuint page_table_unit = UNIT_VIRTUAL_PAGE_TABLE;
  GLuint pool_unit = UNIT_VIRTUAL_POOL;
  // The pool pages' depth bounds (build_bounds()), which backprojection
  // reads; none: not bound.
  std::optional<GLuint> bounds_unit;
};

class VirtualShadowPass {
 public:
  VirtualShadowPass();

  // The client's caster draws, culled per page by update(): one
  // DrawElementsIndirectCommand (count, instance count, first index, base
  // vertex, base instance: 5 words; the instance count and base instance
  // are update()'s) per draw, and each draw's world-space bounds. Until
  // called, there are none.
  void set_draws(std::span<const std::uint32_t> commands, std::span<const CasterBounds> bounds);
  // Draw `draw`'s bounds changed (its casters moved).
  void set_draw_bounds(std::size_t draw, const CasterBounds& bounds);
  [[nodiscard]] int draw_count() const { return draws_; }
  [[nodiscard]] CasterBounds draw_bounds(std::size_t draw) const {
    return {glm::vec3(bounds_data_.at(2 * draw)), glm::vec3(bounds_data_.at(2 * draw + 1))};
  }

  // One frame for `lights` (at most one directional light, and spot
  // lights; levels numbered in this order), fitted to the camera that drew
  // `depth`: marks the pages the depth buffer's pixels read, allocates,
  // lists the pages to render and, for each draw and list, the listed
  // pages its bounds cover. Binds its buffers
  // at the BINDING_VIRTUAL_* storage bindings, BINDING_VIRTUAL_UBO, image
  // unit IMAGE_OUTPUT and texture unit UNIT_GBUFFER_DEPTH (the depth, as
  // With a profiler, the marking and the allocation (with the culling)
  // are timed as GpuPass::VirtualMarking and VirtualAllocation.
  // a 2D texture, and the normals at UNIT_GBUFFER_FACET when given) and
  // leaves them bound.
  void update(std::span<const VirtualLightMaps> lights, const ShadowMapSettings& settings,
              const CameraDepthBuffer& depth, gl::GpuProfiler* profiler = nullptr);
  // A caster moved from world box [lo0, hi0] to [lo1, hi1]: the resident
  // pages either touches render again in the next update().
  void caster_moved(const glm::vec3& lo0, const glm::vec3& hi0, const glm::vec3& lo1,
                    const glm::vec3& hi1);
  // The next update() frees every page and renders what it needs anew.
  void invalidate() { reset_ = true; }

  // Sets what drawing into the pool's pages needs: its layered framebuffer
  // (gl_Layer picks the page), a 128^2 viewport 0, depth test LESS with
  // writes, no face culling, clip control lower-left / 0..1 and viewport
  // 0's depth range 0..1 (end_pages() puts the last two back).
  void begin_pages();
  void end_pages();
  // Clears list `list`'s pages (0: the orthographic levels', 1: the
  // perspective levels') to the far depth (one instanced triangle per
  // page, drawn indirectly; binds GL_DRAW_INDIRECT_BUFFER to commands()
  // and leaves it bound). Between begin_pages() and end_pages().
  void clear_listed_pages(int list);
  // The draw commands: the two clearing draws', then the caster draws' of
  // list `list` at byte draws_offset(list) + 20 d, their instance counts
  // the pages of that list each covers. A page vertex shader reads
  // instance i of draw d's page as render_list[draw_pages[(list * draws +
  // d) * pool_pages + i]] (virtual_page.vert).
  [[nodiscard]] const gl::Buffer& commands() const { return commands_; }
  [[nodiscard]] std::size_t draws_offset(int list) const;
  // After the pages are drawn: each pool page's nearest and farthest depth
  // per cell (virtual_bounds.comp; backprojection's cuts). Binds the pool
  // at UNIT_COMPUTE_INPUT and the bounds at IMAGE_OUTPUT.
  void build_bounds();

  // The pages the last update() listed for rendering: {level, world page
  // x, y, pool page} each, the orthographic levels' then the perspective
  // levels' (a read-back: ShadowMaps draws them one by one through the
  // engine's callback).
  [[nodiscard]] std::vector<glm::ivec4> read_render_list() const;
  // The pages each draw was listed for in the last update(), over both
  // lists (a read-back, for tests and benchmarks).
  [[nodiscard]] std::vector<int> read_page_draws() const;

  // Binds the block, the page table and the pool where the lookup reads
  // them (unsampled: texelFetch).
  void bind(const VirtualBindings& bindings = {}) const;
  [[nodiscard]] VirtualPageStats read_stats() const;
  [[nodiscard]] const gl::Texture& page_table() const { return page_table_; }
  [[nodiscard]] const gl::Texture& pool() const { return pool_; }
  [[nodiscard]] const gl::Texture& bounds() const { return bounds_; }
  [[nodiscard]] const gpu::GpuVirtualShadow& block() const { return block_; }
  [[nodiscard]] const gl::Buffer& block_buffer() const { return block_ubo_; }
  [[nodiscard]] int pool_pages() const { return pool_pages_; }

 private:
  void ensure_pool(int pages);
  void mark_dirty();
  void mark(const CameraDepthBuffer& depth);
  void cull();

  gl::Program mark_program_, allocate_program_, dirty_program_, cull_program_, bounds_program_,
      clear_program_;
  gl::Buffer block_ubo_, counters_, free_list_, render_list_, commands_, draw_bounds_, draw_pages_;
  gl::Texture page_table_, pool_, bounds_;  // bounds_: each pool page's depth bounds per cell
  gl::Framebuffer pool_framebuffer_;
  gl::VertexArray empty_vertex_array_;
  gpu::GpuVirtualShadow block_{};
  std::vector<VirtualLevel> previous_levels_;
  std::vector<std::uint32_t> commands_data_;
  std::vector<glm::vec4> bounds_data_;  // lo, hi per draw
  std::vector<std::pair<glm::vec3, glm::vec3>> moved_boxes_;
  int pool_pages_ = 0;
  int draws_ = 0;
  bool draws_changed_ = true;
  bool reset_ = true;
  GLint saved_clip_origin_ = 0, saved_clip_depth_ = 0;
  GLdouble saved_depth_range_[2] = {0.0, 1.0};
};

}  // namespace penumbra
