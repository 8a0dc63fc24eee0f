// An engine's shadow casters seen from one shadow view (ShadowMaps::render
// in include/penumbra/shadow_maps.hpp): the engine's vertex array gives
// the position at attribute location 0; `model` places it in the world.
// Named as engines' own depth passes name it, so that an engine setting
// "model" by name (glGetUniformLocation) places its objects, as
// CasterView::set_model() does by location.
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "caster_position.glsl"

layout(std140, binding = PENUMBRA_SHADOW_BLOCK_BINDING) uniform PenumbraShadowBlock {
  GpuShadowBlock penumbra;
};

layout(location = 0) uniform int u_view;
layout(location = 1) uniform mat4 model;

layout(location = 0) in vec3 in_position;

out vec3 v_view_position;  // affine in world space, so interpolated exactly

void main() {
  GpuShadowView view = penumbra.views[u_view];
  vec4 world = model * vec4(in_position, 1.0);
  v_view_position = (view.view * world).xyz;
  gl_Position = caster_clip_position(view, world);
}
