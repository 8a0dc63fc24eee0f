// Virtual shadow maps: penumbra's renderer's casters drawn into the
// listed pages, draw u_draw's instance i into the i-th page of its list
// that its bounds cover (virtual_cull.comp lists them): the vertex goes
// through its level's view into the page's square, and to the pool page's
// layer. The depth stored is the level's z-bar: a clipmap level's, as a
// cascade's (caster_position.glsl), is the rasterizer's depth itself
// (orthographic; virtual_page_clip_position()); a spot level's fragments
// write theirs (shadow_depth.frag with VIRTUAL_PAGE), as z-bar is not
// affine in a perspective view's screen space.
#extension GL_ARB_shader_viewport_layer_array : require
#include "../common/uniforms.glsl"
#include "../scene/material.glsl"
#include "../scene/vertex_input.glsl"
#include "caster_position.glsl"
#include "virtual_lookup.glsl"

layout(std430, binding = BINDING_VIRTUAL_RENDER_LIST_SSBO) readonly buffer RenderList {
  ivec4 render_list[];  // x: level, yz: world page, w: pool page
};
layout(std430, binding = BINDING_VIRTUAL_DRAW_PAGES_SSBO) readonly buffer DrawPages {
  uint draw_pages[];  // per list and draw, its instances' indices into render_list
};

layout(location = LOCATION_VIRTUAL_DRAW) uniform int u_draw;
// The list drawn: 0, the orthographic levels' pages, or 1, the
// perspective levels' (VirtualShadowPass::draws_offset()).
layout(location = LOCATION_VIRTUAL_LIST) uniform int u_list;

out vec3 v_view_position;
out vec2 v_texcoord;
out float v_alpha;
flat out uint v_material;
flat out int v_level;

void main() {
  int list_draw = u_list * virtual_shadow.counts.w + u_draw;
  ivec4 page = render_list[draw_pages[list_draw * virtual_shadow.counts.z + gl_InstanceID]];
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
  gl_Position = virtual_page_clip_position(view, page.yz, p);
}
