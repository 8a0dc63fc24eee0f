#include "shadow/shadow_maps_virtual.hpp"

#include <array>
#include <glm/gtc/matrix_transform.hpp>

#include "penumbra/error.hpp"
#include "penumbra/shadow/cascades.hpp"
#include "penumbra/shared/bindings.h"
#include "shadow/gl_state_guard.hpp"
#include "shadow/shadow_lookup.hpp"

namespace penumbra {

namespace {

// The block bind() binds when no light has virtual maps: every light's
// level count 0.
const gpu::GpuVirtualShadow kNoVirtualLight{};

// World -> clip of virtual page `page` (level, world page xy): an
// orthographic box over the page's square in the level's light frame,
// for the engine's culling (virtual_caster.vert draws through the level).
glm::mat4 page_view_projection(const gpu::GpuVirtualShadow& block, const glm::ivec4& page) {
  const gpu::GpuShadowView& level = block.levels[page.x];
  const float size = level.depth_range.z * static_cast<float>(kVirtualPageTexels);
  const glm::vec2 lo = glm::vec2(page.y, page.z) * size;
  return glm::ortho(lo.x, lo.x + size, lo.y, lo.y + size, level.depth_range.x,
                    level.depth_range.y) *
         level.view;
}

}  // namespace

ShadowMapsVirtual::ShadowMapsVirtual(const ShadowBindings& bindings)
    : bindings_(bindings),
      no_virtual_block_(sizeof(gpu::GpuVirtualShadow), &kNoVirtualLight, false,
                        "penumbra no virtual maps") {}

std::span<const GLuint> ShadowMapsVirtual::storage_buffers() {
  static constexpr std::array<GLuint, 7> kBuffers{
      BINDING_VIRTUAL_COUNTERS_SSBO,    BINDING_VIRTUAL_FREE_LIST_SSBO,
      BINDING_VIRTUAL_RENDER_LIST_SSBO, BINDING_VIRTUAL_COMMANDS_SSBO,
      BINDING_VIRTUAL_BLOCK_SSBO,       BINDING_VIRTUAL_DRAW_BOUNDS_SSBO,
      BINDING_VIRTUAL_DRAW_PAGES_SSBO};
  return kBuffers;
}

std::span<const GLuint> ShadowMapsVirtual::texture_2d_units() {
  static constexpr std::array<GLuint, 2> kUnits{UNIT_GBUFFER_DEPTH, UNIT_GBUFFER_FACET};
  return kUnits;
}

void ShadowMapsVirtual::fit(std::span<const Light> lights, const CameraFrustum& camera,
                            PositionSpan positions, std::span<const std::uint32_t> indices,
                            CasterBoundsCache& bounds, const ShadowMapSettings& settings,
                            const CameraDepthBuffer& depth) {
  light_ = -1;
  if (settings.shadow_maps != ShadowMapKind::Virtual) return;
  for (std::size_t i = 0; i < lights.size() && light_ < 0; ++i) {
    if (lights[i].type == LightType::Directional) light_ = static_cast<int>(i);
  }
  if (light_ < 0) return;
  if (settings.technique == Technique::Pcss || settings.technique == Technique::Backprojection) {
    throw UsageError(
        "ShadowMaps: virtual shadow maps take --technique hard or pcf (pcss and backprojection "
        "through virtual maps are penumbra's renderer's); use cascades");
  }
  if (depth.texture == 0 || depth.width <= 0 || depth.height <= 0) {
    throw UsageError(
        "ShadowMaps: virtual shadow maps mark their pages from the camera's depth buffer: "
        "update() needs a CameraDepthBuffer with a texture and its size");
  }
  depth_ = depth;
  light_data_ = lights[static_cast<std::size_t>(light_)];
  const glm::mat4 frame = cascade_light_frame(light_data_);
  clipmap_ = fit_virtual_clipmap(light_data_, camera, depth.height, positions, indices,
                                 bounds.bounds(positions, indices, frame),
                                 clipmap_ ? &*clipmap_ : nullptr);
}

void ShadowMapsVirtual::caster_moved(const CasterBounds& before, const CasterBounds& after) {
  if (pass_) pass_->caster_moved(before.min, before.max, after.min, after.max);
}

void ShadowMapsVirtual::invalidate() {
  if (pass_) pass_->invalidate();
}

int ShadowMapsVirtual::render(const DrawCasters& draw, const ShadowMapSettings& settings,
                              GLuint shadow_block) {
  if (light_ < 0) return 0;
  if (!pass_) {
    pass_.emplace();
    gl::Defines defines = shadow_binding_defines(bindings_);
    defines.emplace_back("RADIAL_DEPTH", "0");
    caster_program_ =
        gl::Program::graphics("shadow/virtual_caster.vert", "shadow/caster_depth.frag", defines);
  }
  const VirtualLightMaps maps{.light_index = light_, .light = light_data_, .maps = *clipmap_};
  pass_->update(std::span(&maps, 1), settings, depth_);
  const std::vector<glm::ivec4> pages = pass_->read_render_list();
  if (pages.empty()) return 0;
  set_caster_pass_state();
  pass_->begin_pages();
  glBindBufferBase(GL_UNIFORM_BUFFER, bindings_.block, shadow_block);
  const GLuint program = caster_program_->id();
  const glm::mat4 identity(1.0f);
  const float far_depth = 1.0f;
  for (std::size_t k = 0; k < pages.size(); ++k) {
    const glm::ivec4& page = pages[k];
    glClearTexSubImage(pass_->pool().id(), 0, 0, 0, page.w, kVirtualPageTexels, kVirtualPageTexels,
                       1, GL_DEPTH_COMPONENT, GL_FLOAT, &far_depth);
    glProgramUniform4i(program, 2, page.x, page.y, page.z, page.w);
    glProgramUniformMatrix4fv(program, CasterView::kModelLocation, 1, GL_FALSE, &identity[0][0]);
    caster_program_->use();
    draw(CasterView{.index = -1,
                    .light = light_,
                    .view_projection = page_view_projection(pass_->block(), page),
                    .program = program,
                    .page = static_cast<int>(k)});
  }
  pass_->end_pages();
  return static_cast<int>(pages.size());
}

void ShadowMapsVirtual::bind() const {
  if (pass_ && light_ >= 0) {
    pass_->bind(VirtualBindings{.block = bindings_.virtual_block,
                                .page_table_unit = bindings_.page_table_unit,
                                .pool_unit = bindings_.page_pool_unit,
                                .bounds_unit = std::nullopt});
    return;
  }
  glBindBufferBase(GL_UNIFORM_BUFFER, bindings_.virtual_block, no_virtual_block_.id());
  for (const GLuint unit : {bindings_.page_table_unit, bindings_.page_pool_unit}) {
    glBindTextureUnit(unit, 0);
    glBindSampler(unit, 0);
  }
}

int ShadowMapsVirtual::pages_resident() const {
  return pass_ && light_ >= 0 ? pass_->read_stats().resident : 0;
}

}  // namespace penumbra
