// An engine's casters in one shadow view, as shadow_depth.frag draws
// penumbra's own scenes (see there, and caster_position.glsl): only a
// point light's radial depth is written (RADIAL_DEPTH 1); every other
// view keeps the rasterizer's depth, and with it the early depth test.
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "lookup.glsl"

#ifndef RADIAL_DEPTH
#define RADIAL_DEPTH 0
#endif

layout(std140, binding = PENUMBRA_SHADOW_BLOCK_BINDING) uniform PenumbraShadowBlock {
  GpuShadowBlock penumbra;
};

layout(location = 0) uniform int u_view;

in vec3 v_view_position;

void main() {
#if RADIAL_DEPTH
  GpuShadowView view = penumbra.views[u_view];
  gl_FragDepth = clamp(relative_depth_of(view, view_space_depth(view, v_view_position)), 0.0, 1.0);
#endif
}
