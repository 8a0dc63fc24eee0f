#include "render/lighting_pass.hpp"

#include <algorithm>
#include <string>

#include "penumbra/gl/context.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

LightingPass::LightingPass()
    : empty_vao_("fullscreen"),
      nearest_(gl::SamplerInfo{
          .min_filter = GL_NEAREST, .mag_filter = GL_NEAREST, .label = "nearest clamp"}),
      bilinear_(gl::SamplerInfo{.label = "bilinear clamp"}),
      compare_(gl::SamplerInfo{.compare_mode = GL_COMPARE_REF_TO_TEXTURE,
                               .label = "bilinear depth compare"}) {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  cpu_rasterizer_ = renderer != nullptr && gl::is_cpu_rasterizer(renderer);
}

namespace {

// The LIGHTING_VIEWS program that writes a VIEW_*.
int lighting_views(int view) {
  if (view == VIEW_FINAL || view == VIEW_SHADOW) return LIGHTING_VIEWS_SHADED;
  if (view == VIEW_SHADOW_REFERENCE) return LIGHTING_VIEWS_REFERENCE;
  return LIGHTING_VIEWS_INSPECT;
}

const char* flag(bool on) {
  return on ? "1" : "0";
}

}  // namespace

bool LightingPass::counts_fetches(const ShadowSettings& settings) {
  return settings.technique == Technique::Pcss || settings.technique == Technique::Backprojection;
}

const gl::Program& LightingPass::program_for(const ShadowSettings& settings, int view) {
  // Only the shaded views march the contact shadows or cast a sub-frame's
  // rays (the reference returns before them, the inspecting views take no
  // lookup): the other views' programs do not differ by them.
  const int views = lighting_views(view);
  const bool shaded = views == LIGHTING_VIEWS_SHADED;
  const ProgramKey key{.technique = technique_define(settings.technique),
                       .filter = filter_define(settings),
                       .quantized_moments = uses_quantized_moments(settings),
                       .soft = settings.soft,
                       .shadow_mips = uses_shadow_mips(settings),
                       .count_fetches = fetch_counts_ != 0 && counts_fetches(settings),
                       .virtual_maps = settings.shadow_maps == ShadowMapKind::Virtual,
                       .views = views,
                       .contact_shadows = shaded && settings.contact_shadows,
                       .accumulate_subframes = shaded && settings.accumulate > 1 &&
                                               settings.technique == Technique::Hard};
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    const gl::Defines defines = {{"SHADOW_TECHNIQUE", std::to_string(key.technique)},
                                 {"SHADOW_FILTER", std::to_string(key.filter)},
                                 {"MSM_QUANTIZED", flag(key.quantized_moments)},
                                 {"SOFT_SHADOWS", flag(key.soft)},
                                 {"SHADOW_MIPS", flag(key.shadow_mips)},
                                 {"SHADOW_COUNT_FETCHES", flag(key.count_fetches)},
                                 {"VIRTUAL_SHADOWS", flag(key.virtual_maps)},
                                 {"LIGHTING_VIEWS", std::to_string(key.views)},
                                 {"CONTACT_SHADOWS", flag(key.contact_shadows)},
                                 {"ACCUMULATE_SUBFRAMES", flag(key.accumulate_subframes)}};
    it = programs_
             .emplace(key, gl::Program::graphics("common/fullscreen.vert", "render/lighting.frag",
                                                 defines))
             .first;
  }
  return it->second;
}

void LightingPass::execute(const GBufferPass& gbuffer, const gl::Texture* depth_maps,
                           GLuint filtered_maps, const ShadowSettings& settings, int view,
                           GLuint ambient_occlusion, int width, int height) {
  if (width != width_ || height != height_) {
    output_ = gl::Texture(gl::TextureInfo{
        .format = GL_RGBA32F, .width = width, .height = height, .label = "lighting output"});
    shadow_output_ = gl::Texture(gl::TextureInfo{
        .format = GL_RGBA32F, .width = width, .height = height, .label = "lighting shadow view"});
    unoccluded_ = gl::Texture(gl::TextureInfo{
        .format = GL_R32F, .width = width, .height = height, .label = "no ambient occlusion"});
    const float one = 1.0f;
    glClearTexImage(unoccluded_.id(), 0, GL_RED, GL_FLOAT, &one);
    framebuffer_ = gl::Framebuffer("lighting");
    framebuffer_.attach_color(0, output_);
    framebuffer_.attach_color(1, shadow_output_);
    framebuffer_.set_draw_buffers(2);
    framebuffer_.check_complete();
    width_ = width;
    height_ = height;
  }

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "lighting");
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  program_for(settings, view).use();
  shadow_view_written_ = lighting_views(view) == LIGHTING_VIEWS_SHADED;
  glBindTextureUnit(UNIT_GBUFFER_DEPTH, gbuffer.depth().id());
  glBindTextureUnit(UNIT_GBUFFER_NORMAL, gbuffer.normal().id());
  glBindTextureUnit(UNIT_GBUFFER_ALBEDO, gbuffer.albedo().id());
  glBindTextureUnit(UNIT_GBUFFER_SPECULAR, gbuffer.specular().id());
  glBindTextureUnit(UNIT_AMBIENT_OCCLUSION,
                    ambient_occlusion != 0 ? ambient_occlusion : unoccluded_.id());
  glBindTextureUnit(UNIT_GBUFFER_FACET, gbuffer.facet().id());
  for (int unit : {UNIT_GBUFFER_DEPTH, UNIT_GBUFFER_NORMAL, UNIT_GBUFFER_ALBEDO,
                   UNIT_GBUFFER_SPECULAR, UNIT_AMBIENT_OCCLUSION, UNIT_GBUFFER_FACET}) {
    glBindSampler(static_cast<GLuint>(unit), nearest_.id());
  }
  // Without shadow maps (Technique::None) the shadow units are never read.
  const GLuint depth = depth_maps != nullptr ? depth_maps->id() : 0;
  glBindTextureUnit(UNIT_SHADOW_DEPTH, depth);
  glBindSampler(UNIT_SHADOW_DEPTH, nearest_.id());
  glBindTextureUnit(UNIT_SHADOW_COMPARE, depth);
  glBindSampler(UNIT_SHADOW_COMPARE, compare_.id());
  // Filtered maps are sampled bilinearly (linear filters commute with the
  // moments' linearity), or trilinearly and anisotropically through their
  // mip chain; integer tables, and backprojection's depth hierarchy at
  // every level, are read with texelFetch (no sampler: a non-mipmapped
  // one would leave only level 0 readable).
  glBindTextureUnit(UNIT_SHADOW_FILTERED, filtered_maps);
  GLuint filtered_sampler = bilinear_.id();
  if (filter_define(settings) == FILTER_SAT || settings.technique == Technique::Backprojection) {
    filtered_sampler = 0;
  }
  if (uses_shadow_mips(settings)) {
    // llvmpipe (Mesa 22.3) ignores textureGrad's derivatives once
    // anisotropic filtering is on: with zero derivatives its lookups still
    // blur across silhouettes, where the implicit derivatives of the
    // deferred pass jump (and the default scene's RMSE against the traced
    // reference rose from 0.033 to 0.089). The CPU rasterizers filter
    // trilinearly only.
    const int anisotropy = cpu_rasterizer_ ? 1 : settings.shadow_anisotropy;
    auto it = trilinear_.find(anisotropy);
    if (it == trilinear_.end()) {
      it =
          trilinear_
              .emplace(anisotropy,
                       gl::Sampler(gl::SamplerInfo{.min_filter = GL_LINEAR_MIPMAP_LINEAR,
                                                   .max_anisotropy = static_cast<float>(anisotropy),
                                                   .label = "trilinear anisotropic clamp"}))
              .first;
    }
    filtered_sampler = it->second.id();
  }
  glBindSampler(UNIT_SHADOW_FILTERED, filtered_sampler);
  if (fetch_counts_ != 0) {
    glBindImageTexture(IMAGE_OUTPUT, fetch_counts_, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  }
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glPopDebugGroup();
}

}  // namespace penumbra
