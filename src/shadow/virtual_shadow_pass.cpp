#include "penumbra/shadow/virtual_shadow_pass.hpp"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <numeric>
#include <stdexcept>

#include "penumbra/shadow/shadow_block_data.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

static_assert(sizeof(gpu::GpuVirtualShadow) ==
                  MAX_VIRTUAL_VIEWS * (sizeof(gpu::GpuShadowView) + 2 * 16) + MAX_LIGHTS * 16 +
                      4 * 16,
              "GpuVirtualShadow must match std140");
static_assert(sizeof(gpu::GpuVirtualShadow) <= 16384, "every OpenGL 4.5 device's block size");

namespace {

// The counters' words (virtual_allocate.comp): free count, taken,
// rendered, unserved, rendered written, the bias, the pages each bias
// wants.
constexpr std::size_t kFreeCount = 0, kRendered = 2, kUnserved = 3, kRenderedWritten = 4, kBias = 5,
                      kCounterWords = 6 + VIRTUAL_LEVEL_BIASES;
// The two lists' clearing draws' commands come first in the command
// buffer, then the caster draws' (5 words each) of the first list, then
// of the second.
constexpr std::size_t kClearCommandWords = 4;
constexpr std::size_t kDrawWords = 5;
// virtual_clear.vert's u_list_start.
constexpr GLint kClearListStart = 0;

}  // namespace

VirtualShadowPass::VirtualShadowPass()
    : mark_program_(gl::Program::compute("shadow/virtual_mark.comp")),
      allocate_program_(gl::Program::compute("shadow/virtual_allocate.comp")),
      dirty_program_(gl::Program::compute("shadow/virtual_dirty.comp")),
      cull_program_(gl::Program::compute("shadow/virtual_cull.comp")),
      bounds_program_(gl::Program::compute("shadow/virtual_bounds.comp")),
      clear_program_(
          gl::Program::graphics("shadow/virtual_clear.vert", "shadow/virtual_clear.frag")),
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
  block_ubo_.update(&block_, sizeof block_);
}

std::size_t VirtualShadowPass::draws_offset(int list) const {
  return (2 * kClearCommandWords +
          static_cast<std::size_t>(list) * kDrawWords * static_cast<std::size_t>(draws_)) *
         sizeof(std::uint32_t);
}

void VirtualShadowPass::set_draws(std::span<const std::uint32_t> commands,
                                  std::span<const CasterBounds> bounds) {
  draws_ = static_cast<int>(bounds.size());
  commands_data_ = {3u, 0u, 0u, 0u, 3u, 0u, 0u, 0u};  // the clearing triangles, one a page
  for (int list = 0; list < 2; ++list) {
    commands_data_.insert(
        commands_data_.end(), commands.begin(),
        commands.begin() + static_cast<std::ptrdiff_t>(kDrawWords * bounds.size()));
  }
  bounds_data_.clear();
  for (const CasterBounds& b : bounds) {
    bounds_data_.emplace_back(b.min, 0.0f);
    bounds_data_.emplace_back(b.max, 0.0f);
  }
  draws_changed_ = true;
}

void VirtualShadowPass::set_draw_bounds(std::size_t draw, const CasterBounds& bounds) {
  bounds_data_.at(2 * draw) = glm::vec4(bounds.min, 0.0f);
  bounds_data_.at(2 * draw + 1) = glm::vec4(bounds.max, 0.0f);
  if (!draws_changed_ && draw_bounds_.id() != 0) {
    draw_bounds_.update(&bounds_data_[2 * draw], 2 * sizeof(glm::vec4),
                        2 * draw * sizeof(glm::vec4));
  }
}

void VirtualShadowPass::ensure_pool(int pages) {
  const bool resized = pages != pool_pages_;
  if (resized) {
    pool_ = gl::Texture(gl::TextureInfo{.target = GL_TEXTURE_2D_ARRAY,
                                        .format = GL_DEPTH_COMPONENT32F,
                                        .width = kVirtualPageTexels,
                                        .height = kVirtualPageTexels,
                                        .layers = pages,
                                        .label = "virtual page pool"});
    bounds_ = gl::Texture(gl::TextureInfo{.target = GL_TEXTURE_2D_ARRAY,
                                          .format = GL_RG32F,
                                          .width = VIRTUAL_BOUNDS_CELLS,
                                          .height = VIRTUAL_BOUNDS_CELLS,
                                          .layers = pages,
                                          .label = "virtual page depth bounds"});
    pool_framebuffer_ = gl::Framebuffer("virtual page pool");
    pool_framebuffer_.attach_depth(pool_);  // layered: gl_Layer picks the page
    pool_framebuffer_.set_draw_buffers(0);
    pool_framebuffer_.check_complete();
    // Each list may hold every page.
    render_list_ = gl::Buffer(2 * static_cast<std::size_t>(pages) * 4 * sizeof(std::int32_t),
                              nullptr, true, "virtual pages to render");
    pool_pages_ = pages;
  }
  if (resized || draws_changed_) {
    // Each draw's pages in each list: at most every listed page.
    const std::size_t entries = std::max<std::size_t>(
        1, 2 * static_cast<std::size_t>(pool_pages_) * static_cast<std::size_t>(draws_));
    draw_pages_ = gl::Buffer(entries * sizeof(std::uint32_t), nullptr, true, "virtual draw pages");
  }
  if (draws_changed_) {
    if (commands_data_.empty()) commands_data_ = {3u, 0u, 0u, 0u, 3u, 0u, 0u, 0u};
    commands_ = gl::Buffer(commands_data_.size() * sizeof(std::uint32_t), commands_data_.data(),
                           true, "virtual page draws");
    if (bounds_data_.empty()) bounds_data_.assign(2, glm::vec4(0.0f));
    draw_bounds_ = gl::Buffer(bounds_data_.size() * sizeof(glm::vec4), bounds_data_.data(), true,
                              "virtual draw bounds");
    draws_changed_ = false;
  }
  if (!resized && !reset_) return;
  // Every page free, none resident.
  std::vector<std::uint32_t> free(static_cast<std::size_t>(pages));
  std::iota(free.begin(), free.end(), 0u);
  free_list_ =
      gl::Buffer(free.size() * sizeof(std::uint32_t), free.data(), true, "virtual page free list");
  std::uint32_t counters[kCounterWords] = {};
  counters[kFreeCount] = static_cast<std::uint32_t>(pages);
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

void VirtualShadowPass::bind(const VirtualBindings& b) const {
  glBindBufferBase(GL_UNIFORM_BUFFER, b.block, block_ubo_.id());
  glBindTextureUnit(b.page_table_unit, page_table_.id());
  glBindSampler(b.page_table_unit, 0);
  glBindTextureUnit(b.pool_unit, pool_.id());
  glBindSampler(b.pool_unit, 0);
  if (b.bounds_unit) {
    glBindTextureUnit(*b.bounds_unit, bounds_.id());
    glBindSampler(*b.bounds_unit, 0);
  }
}

VirtualPageStats VirtualShadowPass::read_stats() const {
  std::uint32_t counters[kCounterWords] = {};
  glGetNamedBufferSubData(counters_.id(), 0, sizeof counters, counters);
  VirtualPageStats stats;
  stats.pool_pages = pool_pages_;
  stats.resident = pool_pages_ - static_cast<int>(counters[kFreeCount]);
  stats.rendered = static_cast<int>(counters[kRendered] + counters[kRenderedWritten]);
  stats.unserved = static_cast<int>(counters[kUnserved]);
  stats.bias = static_cast<int>(counters[kBias]);
  for (const int pages : read_page_draws()) stats.page_draws += pages;
  return stats;
}

std::vector<int> VirtualShadowPass::read_page_draws() const {
  std::vector<int> pages(static_cast<std::size_t>(draws_));
  if (draws_ == 0 || commands_.id() == 0) return pages;
  std::vector<std::uint32_t> words(2 * kDrawWords * static_cast<std::size_t>(draws_));
  glGetNamedBufferSubData(commands_.id(), static_cast<GLintptr>(draws_offset(0)),
                          static_cast<GLsizeiptr>(words.size() * sizeof(std::uint32_t)),
                          words.data());
  for (std::size_t d = 0; d < 2 * pages.size(); ++d)
    pages[d % pages.size()] += static_cast<int>(words[kDrawWords * d + 1]);
  return pages;
}

std::vector<glm::ivec4> VirtualShadowPass::read_render_list() const {
  std::uint32_t counters[kCounterWords] = {};
  glGetNamedBufferSubData(counters_.id(), 0, sizeof counters, counters);
  const auto pool = static_cast<std::size_t>(pool_pages_);
  const std::size_t counts[2] = {std::min<std::size_t>(counters[kRendered], pool),
                                 std::min<std::size_t>(counters[kRenderedWritten], pool)};
  std::vector<glm::ivec4> pages(counts[0] + counts[1]);
  for (int list = 0; list < 2; ++list) {
    if (counts[list] == 0) continue;
    glGetNamedBufferSubData(render_list_.id(),
                            static_cast<GLintptr>(list * pool * sizeof(glm::ivec4)),
                            static_cast<GLsizeiptr>(counts[list] * sizeof(glm::ivec4)),
                            pages.data() + (list == 0 ? 0 : counts[0]));
  }
  return pages;
}

void VirtualShadowPass::update(std::span<const VirtualLightMaps> lights,
                               const ShadowMapSettings& settings, const CameraDepthBuffer& depth,
                               gl::GpuProfiler* profiler) {
  GLint max_layers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  // 16 pages of 64 KiB per MiB.
  ensure_pool(
      std::min(settings.page_pool_mib * 16, std::min(max_layers, int(PAGE_INDEX_MASK) + 1)));

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
    block_.view_axis = glm::vec4(maps.maps.forward, 0.0f);
    for (const VirtualLevel& level : maps.maps.levels) {
      const int l = static_cast<int>(levels_now.size());
      gpu::GpuShadowView view = gpu_shadow_view(maps.light, level.view, settings);
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
  // (half its width, up to twice that on a footprint of two texels, and
  // one texel for its floor; virtual_shadow.glsl), the bilinear taps, and
  // two texels for the lookups' own lift off the surface and rounding.
  const float filter = settings.technique == Technique::Pcf ? settings.pcf_width + 1.0f : 1.0f;
  // PCSS and backprojection also read the source's search region, at
  // coarser levels where it is wider than their window (virtual_mark.comp).
  block_.params.w = settings.technique == Technique::Pcss ? float(VIRTUAL_PCSS_WINDOW)
                    : settings.technique == Technique::Backprojection
                        ? float(VIRTUAL_BACKPROJECTION_WINDOW)
                        : 0.0f;
  block_.params.y = settings.normal_offset + filter + 2.0f;
  block_.counts = glm::ivec4(0, levels, pool_pages_, draws_);
  block_ubo_.update(&block_, sizeof block_);
  previous_levels_ = std::move(levels_now);

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "virtual shadow maps");
  glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_VIRTUAL_UBO, block_ubo_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_COUNTERS_SSBO, counters_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_FREE_LIST_SSBO, free_list_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_RENDER_LIST_SSBO, render_list_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_COMMANDS_SSBO, commands_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_BLOCK_SSBO, block_ubo_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_DRAW_BOUNDS_SSBO, draw_bounds_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_DRAW_PAGES_SSBO, draw_pages_.id());
  glBindImageTexture(IMAGE_OUTPUT, page_table_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  // This frame's counts of rendered and unserved pages start at 0.
  const std::uint32_t zeros[3] = {0, 0, 0};
  counters_.update(zeros, sizeof zeros, kRendered * sizeof(std::uint32_t));

  {
    gl::GpuPassScope timed(profiler, gl::GpuPass::VirtualMarking);
    mark_dirty();
    mark(depth);
  }

  // Allocation: count each bias's pages, choose one, free, take, finish.
  gl::GpuPassScope timed(profiler, gl::GpuPass::VirtualAllocation);
  allocate_program_.use();
  const GLuint program = allocate_program_.id();
  glProgramUniform1i(program, 0, 3);
  glDispatchCompute(gl::work_groups(kVirtualPages, 8), gl::work_groups(kVirtualPages, 8),
                    static_cast<GLuint>(std::max(levels, 1)));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glProgramUniform1i(program, 0, 4);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_UNIFORM_BARRIER_BIT);
  glProgramUniform1i(program, 0, 0);
  glDispatchCompute(gl::work_groups(kVirtualPages, 8), gl::work_groups(kVirtualPages, 8),
                    static_cast<GLuint>(std::max(layers, 1)));
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glProgramUniform1i(program, 0, 1);
  glDispatchCompute(gl::work_groups(kVirtualPages, 8), gl::work_groups(kVirtualPages, 8),
                    static_cast<GLuint>(std::max(levels, 1)));
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glProgramUniform1i(program, 0, 2);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  cull();
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                  GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glPopDebugGroup();
}

void VirtualShadowPass::mark(const CameraDepthBuffer& depth) {
  // World positions from window depth: NDC through the inverse
  // view-projection, inverted in double (the float inverse's rounding
  // would add to the depth buffer's).
  const glm::mat4 inverse = glm::mat4(glm::inverse(glm::dmat4(depth.view_projection)));
  const GLuint program = mark_program_.id();
  glProgramUniformMatrix4fv(program, 0, 1, GL_FALSE, glm::value_ptr(inverse));
  glProgramUniform2i(program, 1, depth.width, depth.height);
  glProgramUniform1i(program, 2, depth.clip_depth == ClipDepth::ZeroToOne ? 1 : 0);
  glProgramUniform1f(program, 3, depth.background_depth);
  glProgramUniform1i(program, 4, depth.normal_texture != 0 ? 1 : 0);
  glBindTextureUnit(UNIT_GBUFFER_DEPTH, depth.texture);
  glBindSampler(UNIT_GBUFFER_DEPTH, 0);
  if (depth.normal_texture != 0) {
    glBindTextureUnit(UNIT_GBUFFER_FACET, depth.normal_texture);
    glBindSampler(UNIT_GBUFFER_FACET, 0);
  }
  mark_program_.use();
  glDispatchCompute(gl::work_groups(depth.width, 8), gl::work_groups(depth.height, 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void VirtualShadowPass::cull() {
  if (draws_ == 0) return;
  // One thread per (listed page, draw) of both lists: the threads past
  // the frame's rendered counts return at once.
  cull_program_.use();
  glDispatchCompute(gl::work_groups(2 * pool_pages_, 64), static_cast<GLuint>(draws_), 1);
}

void VirtualShadowPass::build_bounds() {
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  bounds_program_.use();
  glBindTextureUnit(UNIT_COMPUTE_INPUT, pool_.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindImageTexture(IMAGE_OUTPUT, bounds_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG32F);
  glDispatchCompute(1, 1, static_cast<GLuint>(pool_pages_));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void VirtualShadowPass::mark_dirty() {
  if (moved_boxes_.empty()) return;
  dirty_program_.use();
  const int levels = static_cast<int>(previous_levels_.size());
  for (const auto& [lo, hi] : moved_boxes_) {
    for (int l = 0; l < levels && static_cast<std::size_t>(l) < previous_levels_.size(); ++l) {
      const auto [first, last] =
          virtual_pages_of_box(previous_levels_[static_cast<std::size_t>(l)], lo, hi);
      if (first.x > last.x || first.y > last.y) continue;
      glProgramUniform1i(dirty_program_.id(), 0, l);
      glProgramUniform2i(dirty_program_.id(), 1, first.x, first.y);
      glProgramUniform2i(dirty_program_.id(), 2, last.x, last.y);
      glDispatchCompute(gl::work_groups(last.x - first.x + 1, 8),
                        gl::work_groups(last.y - first.y + 1, 8), 1);
    }
  }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  moved_boxes_.clear();
}

void VirtualShadowPass::begin_pages() {
  glGetIntegerv(GL_CLIP_ORIGIN, &saved_clip_origin_);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &saved_clip_depth_);
  glGetDoublei_v(GL_DEPTH_RANGE, 0, saved_depth_range_);
  // Window depth = clip z exactly: the level's z-bar (as ShadowMapPass).
  // Viewport 0's range and rectangle only: the casters write no
  // gl_ViewportIndex, and an engine's other viewports stay as they were.
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glDepthRangeIndexed(0, 0.0, 1.0);
  glBindFramebuffer(GL_FRAMEBUFFER, pool_framebuffer_.id());
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(kVirtualPageTexels),
                     static_cast<float>(kVirtualPageTexels));
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
}

void VirtualShadowPass::clear_listed_pages(int list) {
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_VIRTUAL_RENDER_LIST_SSBO, render_list_.id());
  glDepthFunc(GL_ALWAYS);
  clear_program_.use();
  // The orthographic levels' pages from render_list[0], the perspective
  // levels' from render_list[pool pages].
  glProgramUniform1i(clear_program_.id(), kClearListStart, list == 0 ? 0 : pool_pages_);
  glBindVertexArray(empty_vertex_array_.id());
  glDrawArraysIndirect(GL_TRIANGLES,
                       reinterpret_cast<const void*>(static_cast<std::size_t>(list) *
                                                     kClearCommandWords * sizeof(std::uint32_t)));
  glDepthFunc(GL_LESS);
}

void VirtualShadowPass::end_pages() {
  glClipControl(static_cast<GLenum>(saved_clip_origin_), static_cast<GLenum>(saved_clip_depth_));
  glDepthRangeIndexed(0, saved_depth_range_[0], saved_depth_range_[1]);
}

}  // namespace penumbra
