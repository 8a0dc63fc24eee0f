// Virtual shadow maps: the casters drawn into the listed pages, one
// instance per page (virtual_allocate.comp lists them): the vertex goes
// through its level's orthographic view into the page's square, and to
// the pool page's layer. The depth written is the level's z-bar, as a
// cascade's (caster_position.glsl): orthographic, so the rasterizer's
// depth is z-bar itself.
#extension GL_ARB_shader_viewport_layer_array : require
#include "../common/uniforms.glsl"
#include "../scene/material.glsl"
#include "../scene/vertex_input.glsl"
#include "virtual_lookup.glsl"

layout(std430, binding = BINDING_VIRTUAL_RENDER_LIST_SSBO) readonly buffer RenderList {
  ivec4 render_list[];  // x: level, yz: world page, w: pool page
};

out vec3 v_view_position;
out vec2 v_texcoord;
out float v_alpha;
flat out uint v_material;

void main() {
  ivec4 page = render_list[gl_InstanceID];
  GpuShadowView view = virtual_shadow.levels[page.x];
  vec4 world = vec4(in_position, 1.0);
  vec3 p = (view.view * world).xyz;
  v_view_position = p;
  v_texcoord = texture_coordinate(materials[in_material], in_uv);
  v_alpha = in_color.a;
  v_material = in_material;
  // The page's square in light space: world page * page size, a power of
  // two times an integer, so every page meets its neighbours exactly.
  float page_size = view.depth_range.z * float(VIRTUAL_PAGE_TEXELS);
  vec2 local = (p.xy - vec2(page.yz) * page_size) / page_size;
  float z_bar = (-p.z - view.depth_range.x) / (view.depth_range.y - view.depth_range.x);
  gl_Position = vec4(local * 2.0 - 1.0, z_bar, 1.0);
  gl_Layer = page.w;
}
