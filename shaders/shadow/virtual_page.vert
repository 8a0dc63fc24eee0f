// Virtual shadow maps: penumbra's renderer's casters drawn into the
// listed pages, draw u_draw's instance i into the i-th page its bounds
// cover (virtual_cull.comp lists them): the vertex goes through its
// level's orthographic view into the page's square, and to the pool
// page's layer (virtual_page_clip_position()).
#extension GL_ARB_shader_viewport_layer_array : require
#include "../common/uniforms.glsl"
#include "../scene/material.glsl"
#include "../scene/vertex_input.glsl"
#include "virtual_lookup.glsl"

layout(std430, binding = BINDING_VIRTUAL_RENDER_LIST_SSBO) readonly buffer RenderList {
  ivec4 render_list[];  // x: level, yz: world page, w: pool page
};
layout(std430, binding = BINDING_VIRTUAL_DRAW_PAGES_SSBO) readonly buffer DrawPages {
  uint draw_pages[];  // per draw, its instances' indices into render_list
};

layout(location = LOCATION_VIRTUAL_DRAW) uniform int u_draw;

out vec3 v_view_position;
out vec2 v_texcoord;
out float v_alpha;
flat out uint v_material;

void main() {
  ivec4 page = render_list[draw_pages[u_draw * virtual_shadow.counts.z + gl_InstanceID]];
  GpuShadowView view = virtual_shadow.levels[page.x];
  vec4 world = vec4(in_position, 1.0);
  vec3 p = (view.view * world).xyz;
  v_view_position = p;
  v_texcoord = texture_coordinate(materials[in_material], in_uv);
  v_alpha = in_color.a;
  v_material = in_material;
  gl_Position = virtual_page_clip_position(view, page.yz, p);
  gl_Layer = page.w;
}
