// Writes the relative depth z-bar of an engine's caster, as
// shadow_depth.frag does for penumbra's own scenes (see there why it is
// linear in light-space distance).
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "lookup.glsl"

layout(std140, binding = PENUMBRA_SHADOW_BLOCK_BINDING) uniform PenumbraShadowBlock {
  GpuShadowBlock penumbra;
};

layout(location = 0) uniform int u_view;

in vec3 v_view_position;
layout(depth_any) out float gl_FragDepth;

void main() {
  GpuShadowView view = penumbra.views[u_view];
  gl_FragDepth = clamp(relative_depth_of(view, view_space_depth(view, v_view_position)), 0.0, 1.0);
}
