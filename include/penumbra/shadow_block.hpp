#pragma once
// The uniform block the shadow lookup reads (std140), as the C++ struct
// ShadowMaps fills: penumbra::ShadowBlock. An engine does not write it; it
// binds it with ShadowMaps::bind() and reads it from GLSL through
// penumbra_shadow() (see penumbra/shadow_maps.hpp). Shared with the GLSL
// (one declaration for both), so the layouts cannot drift; the sizes below
// are std140's, and a GPU test compares the offsets with the driver's.
// Where the block and the maps are bound is the engine's choice, made at
// run time: ShadowBindings below, given to ShadowMaps and to
// shadow_lookup_glsl().
// The struct's one declaration, compiled by the GLSL too (shaders/shared/,
// installed as include/penumbra/shared/).
#include "penumbra/shared/gpu_types.h"

namespace penumbra {

using ShadowBlock = gpu::GpuShadowBlock;
using ShadowParams = gpu::GpuShadow;
using ShadowLightData = gpu::GpuLight;
using ShadowViewData = gpu::GpuShadowView;

// std140 sizes: vec4, mat4 and ivec4 members only, scalars four to a row.
static_assert(sizeof(ShadowParams) == 144, "GpuShadow must match std140");
static_assert(sizeof(ShadowLightData) == 6 * 16, "GpuLight must match std140");
static_assert(sizeof(ShadowViewData) == 3 * 64 + 2 * 16, "GpuShadowView must match std140");
static_assert(sizeof(ShadowBlock) ==
                  144 + 64 + 16 + MAX_LIGHTS * (6 * 16) + MAX_SHADOW_VIEWS * (3 * 64 + 2 * 16),
              "GpuShadowBlock must match std140");

inline constexpr int kMaxLights = MAX_LIGHTS;
inline constexpr int kMaxShadowViews = MAX_SHADOW_VIEWS;
inline constexpr int kMaxCascades = MAX_CASCADES;

// The binding points the lookup reads (penumbra_shadow() in GLSL) and
// ShadowMaps::bind() binds: the engine chooses them, so that they stay
// clear of its own. Give the same value to ShadowMaps' constructor and to
// shadow_lookup_glsl(), which declares the block, the samplers and the
// buffer at exactly these bindings (and defines them as the GLSL macros
// named beside each field, for the engine's shader to read). The six
// texture units must differ; each binding must be below the context's
// limit (GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, GL_MAX_UNIFORM_BUFFER_BINDINGS,
// GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS; ShadowMaps checks them).
struct ShadowBindings {
  // Uniform buffer binding of the ShadowBlock (PENUMBRA_SHADOW_BLOCK_BINDING).
  // ShadowMaps::render() binds it too, for its caster program.
  unsigned block = 7;
  // Texture unit of the z-bar depth maps, a sampler2DArray read with a
  // nearest sampler (PENUMBRA_SHADOW_DEPTH_UNIT).
  unsigned depth_unit = 13;
  // Texture unit of the technique's filtered representation, bilinear
  // (PENUMBRA_SHADOW_FILTERED_UNIT).
  unsigned filtered_unit = 14;
  // Texture unit of the depth maps through a comparison sampler, a
  // sampler2DArrayShadow (PENUMBRA_SHADOW_COMPARE_UNIT).
  unsigned compare_unit = 15;
  // Texture unit of the summed-area tables, a usampler2DArray
  // (Filter::Sat; PENUMBRA_SHADOW_SAT_UNIT).
  unsigned sat_unit = 12;
  // Shader storage buffer binding of PCF's and PCSS's sample set
  // (PENUMBRA_POISSON_BINDING).
  unsigned poisson_buffer = 2;
  // Virtual shadow maps (ShadowMapKind::Virtual): the uniform buffer
  // binding of their block (PENUMBRA_SHADOW_VIRTUAL_BLOCK_BINDING, bound
  // by bind() whatever the kind: it says which light has virtual maps), and
  // the texture units of the page table, a usampler2DArray
  // (PENUMBRA_SHADOW_PAGE_TABLE_UNIT), and of the page pool, a
  // sampler2DArray (PENUMBRA_SHADOW_PAGE_POOL_UNIT), both read texel by
  // texel. ShadowMaps::render() binds the block at the binding too.
  unsigned virtual_block = 8;
  unsigned page_table_unit = 10;
  unsigned page_pool_unit = 11;

  friend bool operator==(const ShadowBindings&, const ShadowBindings&) = default;
};

}  // namespace penumbra
