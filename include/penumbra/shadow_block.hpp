#pragma once
// The uniform block the shadow lookup reads (std140), as the C++ struct
// ShadowMaps fills: penumbra::ShadowBlock. An engine does not write it; it
// binds it with ShadowMaps::bind() and reads it from GLSL through
// penumbra_shadow() (see penumbra/shadow_maps.hpp). Shared with the GLSL
// (one declaration for both), so the layouts cannot drift; the sizes below
// are std140's, and a GPU test compares the offsets with the driver's.
//
// Binding points (each a macro an engine may define before including
// this header and before the GLSL, to move it):
//   PENUMBRA_SHADOW_BLOCK_BINDING  uniform buffer, the ShadowBlock   (default 7)
//   PENUMBRA_UNIT_SHADOW_DEPTH     texture unit, z-bar depth maps    (default 13)
//   PENUMBRA_UNIT_SHADOW_FILTERED  texture unit, filtered maps       (default 14)
//   PENUMBRA_UNIT_SHADOW_COMPARE   texture unit, comparison sampler  (default 15)
//   PENUMBRA_UNIT_SHADOW_SAT       texture unit, summed-area tables  (default 12)
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
inline constexpr unsigned kShadowBlockBinding = PENUMBRA_SHADOW_BLOCK_BINDING;
inline constexpr unsigned kShadowDepthUnit = PENUMBRA_UNIT_SHADOW_DEPTH;
inline constexpr unsigned kShadowFilteredUnit = PENUMBRA_UNIT_SHADOW_FILTERED;
inline constexpr unsigned kShadowCompareUnit = PENUMBRA_UNIT_SHADOW_COMPARE;
inline constexpr unsigned kShadowSatUnit = PENUMBRA_UNIT_SHADOW_SAT;

}  // namespace penumbra
