#include "render/virtual_shadow_pass.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "penumbra/shadow/shadow_block_data.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

static_assert(sizeof(gpu::GpuVirtualShadow) ==
                  MAX_VIRTUAL_VIEWS * (sizeof(gpu::GpuShadowView) + 2 * 16) + MAX_LIGHTS * 16 +
                      3 * 16,
              "GpuVirtualShadow must match std140");
static_assert(sizeof(gpu::GpuVirtualShadow) <= 16384, "every OpenGL 4.5 device's block size");

namespace {

// The counters' words (virtual_allocate.comp).
constexpr std::size_t kFreeCount = 0, kRendered = 2, kUnserved = 3, kRenderedWritten = 4,
                      kCounterWords = 5;
// The two lists' clearing draws' commands come first in the command
// buffer, then the batches' (5 words each) of the first list, then of the
// second.
constexpr std::size_t kClearCommandWords = 4;
// virtual_clear.vert's and virtual_page.vert's u_list_start.
constexpr GLint kClearListStart = 0, kPageListStart = 1;

// The orthographic levels' pages keep the rasterizer's depth; the
// perspective levels' fragments write their z-bar (virtual_page.vert).
gl::Program page_program(bool cut_outs, bool written_depth) {
  return gl::Program::graphics("shadow/virtual_page.vert", "shadow/shadow_depth.frag",
                               {{"RADIAL_DEPTH", written_depth ? "1" : "0"},
                                {"VIRTUAL_PAGE", written_depth ? "1" : "0"},
                                {"CUT_OUTS", cut_outs ? "1" : "0"}});
}

GLuint groups(int n, int size) {
  return static_cast<GLuint>((n + size - 1) / size);
}

}  // namespace

VirtualShadowPass::VirtualShadowPass()
    : mark_program_(gl::Program::compute("shadow/virtual_mark.comp")),
      allocate_program_(gl::Program::compute("shadow/virtual_allocate.comp")),
      dirty_program_(gl::Program::compute("shadow/virtual_dirty.comp")),
      clear_program_(
          gl::Program::graphics("shadow/virtual_clear.vert", "shadow/virtual_clear.frag")),
      page_programs_{page_program(false, false), page_program(true, false)},
      written_page_programs_{page_program(false, true), page_program(true, true)},
      block_ubo_(sizeof(gpu::GpuVirtualShadow), nullptr, true, "virtual shadow block"),
      counters_(kCounterWords * sizeof(std::uint32_t), nullptr, true, "virtual page counters"),
      page_table_(gl::TextureInfo{.target = GL_TEXTURE_2D_ARRAY,
                                  .format = GL_R32UI,
                                  .width = kVirtualPages,
                                  .height = kVirtualPages,
                                  .layers = kMaxVirtualViews,
                                  .label = "virtual page table"}),
      empty_vertex_array_("virtual page clear") {
  block_.counts = glm::ivec4(0);
}

void VirtualShadowPass::ensure_pool(int pages) {
  if (pages == pool_pages_ && !reset_) return;
  if (pages != pool_pages_) {
    pool_ = gl::Texture(gl::TextureInfo{.target = GL_TEXTURE_2D_ARRAY,
                                        .format = GL_DEPTH_COMPONENT32F,
                                        .width = kVirtualPageTexels,
                                        .height = kVirtualPageTexels,
                                        .layers = pages,
                                        .label = "virtual page pool"});
    pool_framebuffer_ = gl::Framebuffer("virtual page pool");
    pool_framebuffer_.attach_depth(pool_);  // layered: gl_Layer picks the page
    pool_framebuffer_.set_draw_buffers(0);
    pool_framebuffer_.check_complete();
    // Each list may hold every page.
    render_list_ = gl::Buffer(2 * static_cast<std::size_t>(pages) * 4 * sizeof(std::int32_t),
                              nullptr, true, "virtual pages to render");
    pool_pages_ = pages;
  }
  // Every page free, none resident.
  std::vector<std::uint32_t> free(static_cast<std::size_t>(pages));
  std::iota(free.begin(), free.end(), 0u);
  free_list_ =
      gl::Buffer(free.size() * sizeof(std::uint32_t), free.data(), true, "virtual page free list");
  const std::uint32_t counters[kCounterWords] = {static_cast<std::uint32_t>(pages), 0, 0, 0, 0};
  counters_.update(counters, sizeof counters);
  const GLuint zero = 0;
  glClearTexImage(page_table_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  previous_levels_.clear();
  moved_boxes_.clear();
  reset_ = false;
}

void VirtualShadowPass::caster_moved(const glm::vec3& lo0, const glm::vec3& hi0,
                                     const glm::vec3& lo1, const glm::vec3& hi1) {
  moved_boxes_.emplace_back(lo0, hi0);
  moved_boxes_.emplace_back(lo1, hi1);
}

void VirtualShadowPass::bind() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_VIRTUAL_UBO, block_ubo_.id());
  glBindTextureUnit(UNIT_VIRTUAL_PAGE_TABLE, page_table_.id());
  glBindSampler(UNIT_VIRTUAL_PAGE_TABLE, 0);
  glBindTextureUnit(UNIT_VIRTUAL_POOL, pool_.id());
  glBindSampler(UNIT_VIRTUAL_POOL, 0);
}

VirtualPageStats VirtualShadowPass::read_stats() const {
  std::uint32_t counters[kCounterWords] = {};
  glGetNamedBufferSubData(counters_.id(), 0, sizeof counters, counters);
  VirtualPageStats stats;
  stats.pool_pages = pool_pages_;
  stats.resident = pool_pages_ - static_cast<int>(counters[kFreeCount]);
  stats.rendered = static_cast<int>(counters[kRendered] + counters[kRenderedWritten]);
  stats.unserved = static_cast<int>(counters[kUnserved]);
  return stats;
}

void VirtualShadowPass::execute(std::span<const VirtualLightMaps> lights,
                                const ShadowSettings& shadow, const GBufferPass& gbuffer,
                                const GpuScene& scene) {
  GLint max_layers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  // 16 pages of 64 KiB per MiB.
  ensure_pool(std::min(shadow.page_pool_mib * 16, std::min(max_layers, int(PAGE_INDEX_MASK) + 1)));
  if (commands_data_.empty()) {
    commands_data_ = {3u, 0u, 0u, 0u, 3u, 0u, 0u, 0u};  // the clearing triangles
    const std::vector<std::uint32_t> batches = scene.indirect_commands();
    for (int list = 0; list < 2; ++list)
      commands_data_.insert(commands_data_.end(), batches.begin(), batches.end());
    commands_ = gl::Buffer(commands_data_.size() * sizeof(std::uint32_t), commands_data_.data(),
                           true, "virtual page draws");
  }

  // The block: one view per level, light after light, and what changed
  // since the last frame.
  std::vector<VirtualLevel> levels_now;
  block_ = gpu::GpuVirtualShadow{};
  for (const VirtualLightMaps& maps : lights) {
    const int first = static_cast<int>(levels_now.size());
    const int count = static_cast<int>(maps.maps.levels.size());
    if (first + count > kMaxVirtualViews || maps.light_index < 0 ||
        maps.light_index >= MAX_LIGHTS) {
      throw std::logic_error("virtual shadow maps: too many levels or a light out of range");
    }
    block_.lights[maps.light_index] = glm::ivec4(first, count, 0, 0);
    if (!maps.maps.levels.front().view.perspective) block_.params.x = maps.maps.texel0;
    block_.camera = glm::vec4(maps.maps.camera, maps.maps.pixel_angle);
    for (const VirtualLevel& level : maps.maps.levels) {
      const int l = static_cast<int>(levels_now.size());
      gpu::GpuShadowView view = gpu_shadow_view(maps.light, level.view, shadow);
      view.depth_range.w = static_cast<float>(level.texels);
      block_.levels[l] = view;
      bool same = static_cast<std::size_t>(l) < previous_levels_.size();
      glm::ivec2 previous = level.origin;
      if (same) {
        const VirtualLevel& before = previous_levels_[static_cast<std::size_t>(l)];
        // A clipmap level's projection follows its origin (its pages
        // scroll); a spot level's is its own.
        same = before.view.z0 == level.view.z0 && before.view.z1 == level.view.z1 &&
               before.view.texel_world == level.view.texel_world &&
               before.view.view == level.view.view && before.texels == level.texels &&
               before.view.perspective == level.view.perspective &&
               (!level.view.perspective || before.view.projection == level.view.projection);
        previous = before.origin;
      }
      block_.origins[l] = glm::ivec4(level.origin, same ? 0 : 1, previous != level.origin ? 1 : 0);
      block_.previous_origins[l] = glm::ivec4(same ? previous : level.origin, 0, 0);
      levels_now.push_back(level);
    }
  }
  const int levels = static_cast<int>(levels_now.size());
  // Phase 0 frees the pages of the levels gone since the last frame too.
  const int layers = std::max(levels, static_cast<int>(previous_levels_.size()));
  // What a lookup reads around its texel: the normal offset, PCF's window
  // (half its width, and one texel for its floor), the bilinear taps, and
  // two texels for the lookups' own lift off the surface and rounding.
  const float filter = shadow.technique == Technique::Pcf ? 0.5f * shadow.pcf_width + 1.0f : 1.0f;
  block_.params.y = shadow.normal_offset + filter + 2.0f;
  const int batch_words = static_cast<int>(commands_data_.size() - 2 * kClearCommandWords) / 2;
  block_.counts = glm::ivec4(0, levels, pool_pages_, batch_words / 5);
  block_ubo_.update(&block_, sizeof block_);
  previous_levels_ = std::move(levels_now);

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "virtual shadow maps");
  glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_VIRTUAL_UBO, block_ubo_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_COUNTERS_SSBO, counters_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_FREE_LIST_SSBO, free_list_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_RENDER_LIST_SSBO, render_list_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_COMMANDS_SSBO, commands_.id());
  glBindImageTexture(IMAGE_OUTPUT, page_table_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  // This frame's counts of rendered and unserved pages start at 0.
  const std::uint32_t zeros[3] = {0, 0, 0};
  counters_.update(zeros, sizeof zeros, kRendered * sizeof(std::uint32_t));

  mark_dirty();

  // Marking, over the camera's pixels.
  glBindTextureUnit(UNIT_GBUFFER_DEPTH, gbuffer.depth().id());
  glBindSampler(UNIT_GBUFFER_DEPTH, 0);
  glBindTextureUnit(UNIT_GBUFFER_NORMAL, gbuffer.normal().id());
  glBindSampler(UNIT_GBUFFER_NORMAL, 0);
  mark_program_.use();
  glDispatchCompute(groups(gbuffer.depth().width(), 8), groups(gbuffer.depth().height(), 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

  // Allocation: free, take, finish.
  allocate_program_.use();
  const GLuint program = allocate_program_.id();
  glProgramUniform1i(program, 0, 0);
  glDispatchCompute(groups(kVirtualPages, 8), groups(kVirtualPages, 8),
                    static_cast<GLuint>(std::max(layers, 1)));
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glProgramUniform1i(program, 0, 1);
  glDispatchCompute(groups(kVirtualPages, 8), groups(kVirtualPages, 8),
                    static_cast<GLuint>(std::max(levels, 1)));
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glProgramUniform1i(program, 0, 2);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                  GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

  render_pages(scene, batch_words);
  glPopDebugGroup();
}

void VirtualShadowPass::mark_dirty() {
  if (moved_boxes_.empty()) return;
  dirty_program_.use();
  const int levels = static_cast<int>(previous_levels_.size());
  for (const auto& [lo, hi] : moved_boxes_) {
    for (int l = 0; l < levels; ++l) {
      const auto [first, last] =
          virtual_pages_of_box(previous_levels_[static_cast<std::size_t>(l)], lo, hi);
      if (first.x > last.x || first.y > last.y) continue;
      glProgramUniform1i(dirty_program_.id(), 0, l);
      glProgramUniform2i(dirty_program_.id(), 1, first.x, first.y);
      glProgramUniform2i(dirty_program_.id(), 2, last.x, last.y);
      glDispatchCompute(groups(last.x - first.x + 1, 8), groups(last.y - first.y + 1, 8), 1);
    }
  }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  moved_boxes_.clear();
}

void VirtualShadowPass::render_pages(const GpuScene& scene, int batch_words) {
  GLint clip_origin = GL_LOWER_LEFT, clip_depth = GL_NEGATIVE_ONE_TO_ONE;
  GLfloat depth_range[2] = {0.0f, 1.0f};
  glGetIntegerv(GL_CLIP_ORIGIN, &clip_origin);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &clip_depth);
  glGetFloatv(GL_DEPTH_RANGE, depth_range);
  // Window depth = clip z exactly: the level's z-bar (as ShadowMapPass).
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glDepthRangef(0.0f, 1.0f);
  glBindFramebuffer(GL_FRAMEBUFFER, pool_framebuffer_.id());
  glViewport(0, 0, kVirtualPageTexels, kVirtualPageTexels);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.id());
  // The two lists: the orthographic levels' pages from render_list[0],
  // the perspective levels' from render_list[pool pages].
  const std::size_t word = sizeof(std::uint32_t);
  const std::size_t batches = 2 * kClearCommandWords * word;
  for (int list = 0; list < 2; ++list) {
    const GLint start = list == 0 ? 0 : pool_pages_;
    // Clear the listed pages to the far depth.
    glDepthFunc(GL_ALWAYS);
    clear_program_.use();
    glProgramUniform1i(clear_program_.id(), kClearListStart, start);
    glBindVertexArray(empty_vertex_array_.id());
    glDrawArraysIndirect(GL_TRIANGLES,
                         reinterpret_cast<const void*>(list * kClearCommandWords * word));
    // The casters, one instance per listed page.
    glDepthFunc(GL_LESS);
    const std::size_t offset = batches + static_cast<std::size_t>(list * batch_words) * word;
    const gl::Program* programs = list == 0 ? page_programs_ : written_page_programs_;
    for (int cut_outs = 0; cut_outs < 2; ++cut_outs) {
      programs[cut_outs].use();
      glProgramUniform1i(programs[cut_outs].id(), kPageListStart, start);
      scene.draw_indirect(cut_outs == 0 ? SurfaceSet::Opaque : SurfaceSet::CutOut, offset);
    }
  }
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glClipControl(static_cast<GLenum>(clip_origin), static_cast<GLenum>(clip_depth));
  glDepthRangef(depth_range[0], depth_range[1]);
}

}  // namespace penumbra
