#pragma once
// Virtual shadow maps for a list of lights (docs/rendering.md, "Virtual
// shadow maps"): a directional light's clipmap, a spot light's mip levels,
// their pages in one pool and their levels' entries in one page table
// (a layer per level). Each frame, marks the pages the camera's pixels
// read (a compute pass over the G-buffer), allocates pool pages for the
// new ones and frees the unrequested ones (compute, with a free list and
// atomic counters), and draws the casters into only the pages listed for
// rendering (indirect instanced draws, one instance per page). Pages stay
// cached while they are requested and nothing over them moved. No
// read-back in the frame: read_stats() is for benchmarks and tests.
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/virtual_clipmap.hpp"
#include "penumbra/shared/gpu_types.h"
#include "render/gbuffer_pass.hpp"
#include "render/gpu_scene.hpp"

namespace penumbra {

// What the last frames did with the pages (read back from the GPU).
struct VirtualPageStats {
  int pool_pages = 0;  // the pool's size
  int resident = 0;    // pages holding depths (allocated)
  int rendered = 0;    // pages drawn by the last execute()
  int unserved = 0;    // requested pages the pool had no room for in the last execute()
};

// One light's virtual maps in a frame: scene light `light_index`, its
// clipmap (directional) or mip levels (spot), fitted to the frame's camera.
struct VirtualLightMaps {
  int light_index = -1;
  Light light;
  VirtualClipmap maps;
};

class VirtualShadowPass {
 public:
  VirtualShadowPass();

  // One frame for `lights` (at most one directional light, and spot
  // lights; levels numbered in this order): marks from `gbuffer` (drawn
  // for the camera the maps were fitted to; the frame block must be
  // bound), allocates, and draws `scene`'s casters into the pages that
  // need it.
  void execute(std::span<const VirtualLightMaps> lights, const ShadowSettings& shadow,
               const GBufferPass& gbuffer, const GpuScene& scene);
  // A caster moved from world box [lo0, hi0] to [lo1, hi1]: the resident
  // pages either touches render again in the next execute().
  void caster_moved(const glm::vec3& lo0, const glm::vec3& hi0, const glm::vec3& lo1,
                    const glm::vec3& hi1);
  // The next execute() frees every page and renders what it needs anew.
  void invalidate() { reset_ = true; }

  // Binds the block (BINDING_VIRTUAL_UBO), the page table and the pool
  // (UNIT_VIRTUAL_PAGE_TABLE, UNIT_VIRTUAL_POOL) for the lighting pass.
  void bind() const;
  [[nodiscard]] VirtualPageStats read_stats() const;
  [[nodiscard]] const gl::Texture& page_table() const { return page_table_; }
  [[nodiscard]] const gl::Texture& pool() const { return pool_; }
  [[nodiscard]] const gpu::GpuVirtualShadow& block() const { return block_; }

 private:
  void ensure_pool(int pages);
  void mark_dirty();
  void render_pages(const GpuScene& scene, int batch_words);

  gl::Program mark_program_, allocate_program_, dirty_program_, clear_program_;
  gl::Program page_programs_[2];          // opaque, cut-outs: orthographic levels
  gl::Program written_page_programs_[2];  // the same: perspective levels (depth written)
  gl::Buffer block_ubo_, counters_, free_list_, render_list_, commands_;
  gl::Texture page_table_, pool_;
  gl::Framebuffer pool_framebuffer_;
  gl::VertexArray empty_vertex_array_;
  gpu::GpuVirtualShadow block_{};
  std::vector<VirtualLevel> previous_levels_;
  std::vector<std::uint32_t> commands_data_;
  std::vector<std::pair<glm::vec3, glm::vec3>> moved_boxes_;
  int pool_pages_ = 0;
  bool reset_ = true;
};

}  // namespace penumbra
