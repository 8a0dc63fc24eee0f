#pragma once
// The shadow blocks' contents (shaders/shared/gpu_types.h) from the lights,
// their fitted views and the settings: one conversion for penumbra's
// renderer and for ShadowMaps alike, so both look shadows up from the same
// numbers.
#include "penumbra/light.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/light_view.hpp"
#include "penumbra/shadow/shadow_views.hpp"
#include "penumbra/shared/gpu_types.h"

namespace penumbra {

// The LIGHT_* define of a light type.
int light_type_define(LightType type);

// Light i's entry of the lights block; its views are first_view.. of the
// views block.
gpu::GpuLight gpu_light(const Light& light, const LightShadowViews& views, int first_view,
                        const ShadowMapSettings& shadow);

// One view's entry of the shadow-views block.
gpu::GpuShadowView gpu_shadow_view(const Light& light, const LightView& view,
                                   const ShadowMapSettings& shadow);

// The shadow parameters block for the settings. The fields a renderer sets
// per sub-frame (accumulate_*) are left for it: 0.
gpu::GpuShadow gpu_shadow_params(const ShadowMapSettings& shadow);

}  // namespace penumbra
