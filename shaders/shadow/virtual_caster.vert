// An engine's casters drawn into one virtual shadow-map page
// (ShadowMaps::render with ShadowMapKind::Virtual): as caster_depth.vert,
// the position at attribute location 0 placed in the world by `model`,
// then through the page's level into the page's square and to its pool
// page's layer (virtual_page_clip_position()).
#extension GL_ARB_shader_viewport_layer_array : require
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "virtual_lookup.glsl"

layout(location = 1) uniform mat4 model;
layout(location = 2) uniform ivec4 u_page;  // x: level, yz: world page, w: pool page

layout(location = 0) in vec3 in_position;

out vec3 v_view_position;

void main() {
  GpuShadowView view = virtual_shadow.levels[u_page.x];
  vec3 p = (view.view * (model * vec4(in_position, 1.0))).xyz;
  v_view_position = p;
  gl_Position = virtual_page_clip_position(view, u_page.yz, p);
  gl_Layer = u_page.w;
}
