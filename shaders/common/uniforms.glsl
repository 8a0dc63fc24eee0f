// The uniform blocks every pass of a frame may read.
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"

layout(std140, binding = BINDING_FRAME_UBO) uniform FrameBlock { GpuFrame frame; };
layout(std140, binding = BINDING_LIGHTS_UBO) uniform LightsBlock { GpuLight lights[MAX_LIGHTS]; };
layout(std140, binding = BINDING_SHADOW_VIEWS_UBO) uniform ShadowViewsBlock {
  GpuShadowView shadow_views[MAX_SHADOW_VIEWS];
};
