// Virtual shadow maps: the casters drawn into the listed pages, one
// instance per page (virtual_allocate.comp lists them): the vertex goes
// through its level's view into the page's square, and to the pool page's
// layer. The depth stored is the level's z-bar: a clipmap level's, as a
// cascade's (caster_position.glsl), is the rasterizer's depth itself
// (orthographic); a spot level's fragments write theirs (shadow_depth.frag
// with VIRTUAL_PAGE), as z-bar is not affine in a perspective view's
// screen space.
#extension GL_ARB_shader_viewport_layer_array : require
#include "../common/uniforms.glsl"
#include "../scene/material.glsl"
#include "../scene/vertex_input.glsl"
#include "caster_position.glsl"
#include "virtual_lookup.glsl"

layout(std430, binding = BINDING_VIRTUAL_RENDER_LIST_SSBO) readonly buffer RenderList {
  ivec4 render_list[];  // x: level, yz: world page, w: pool page
};
// Where this draw's list starts (virtual_allocate.comp: the perspective
// levels' pages follow the pool's page count).
layout(location = 1) uniform int u_list_start;

out vec3 v_view_position;
out vec2 v_texcoord;
out float v_alpha;
flat out uint v_material;
flat out int v_level;

void main() {
  ivec4 page = render_list[u_list_start + gl_InstanceID];
  GpuShadowView view = virtual_shadow.levels[page.x];
  vec4 world = vec4(in_position, 1.0);
  vec3 p = (view.view * world).xyz;
  v_view_position = p;
  v_texcoord = texture_coordinate(materials[in_material], in_uv);
  v_alpha = in_color.a;
  v_material = in_material;
  v_level = page.x;
  gl_Layer = page.w;
  if (view.perspective != 0) {
    // The spot's own clip position (depth z0 / z: its near plane clips as
    // the conventional map's does), its xy scaled and moved so that the
    // page's square of the level's [0, 1]^2 fills the viewport.
    vec4 clip = caster_clip_position(view, world);
    float pages = float(virtual_level_texels(page.x) / VIRTUAL_PAGE_TEXELS);
    clip.xy = (clip.xy + clip.w) * pages - clip.w * (2.0 * vec2(page.yz) + 1.0);
    gl_Position = clip;
    return;
  }
  // The page's square in light space: world page * page size, a power of
  // two times an integer, so every page meets its neighbours exactly.
  float page_size = view.depth_range.z * float(VIRTUAL_PAGE_TEXELS);
  vec2 local = (p.xy - vec2(page.yz) * page_size) / page_size;
  float z_bar = (-p.z - view.depth_range.x) / (view.depth_range.y - view.depth_range.x);
  gl_Position = vec4(local * 2.0 - 1.0, z_bar, 1.0);
}
