// Shadow pass: the scene seen from one shadow view.
#include "../common/uniforms.glsl"
#include "../scene/material.glsl"
#include "../scene/vertex_input.glsl"
#include "caster_position.glsl"

layout(location = 0) uniform int u_view;

out vec3 v_view_position;  // view-space position: interpolated exactly (it is affine in world)
out vec2 v_texcoord;  // in the base-colour texture
out float v_alpha;
flat out uint v_material;

void main() {
  GpuShadowView view = shadow_views[u_view];
  vec4 world = vec4(in_position, 1.0);
  v_view_position = (view.view * world).xyz;
  v_texcoord = texture_coordinate(materials[in_material], in_uv);
  v_alpha = in_color.a;
  v_material = in_material;
  gl_Position = caster_clip_position(view, world);
}
