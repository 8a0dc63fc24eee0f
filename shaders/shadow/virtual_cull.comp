// Virtual shadow maps, per-page caster culling: one thread per (listed
// page, caster draw). A draw is listed for a page only where its world
// bounds, seen down the light (the box's eight corners in the level's
// light frame), cover the page's square widened by one texel (the
// margin virtual_pages_of_box() gives a moved caster, for the filters'
// taps at the page's edge). Its command's instance count is the number
// of pages listed; draw_pages[d * pool pages + i] is instance i's index
// into the render list (virtual_page.vert reads it).
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "virtual_lookup.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = BINDING_VIRTUAL_COUNTERS_SSBO) readonly buffer Counters {
  uint free_count;
  uint taken;
  uint rendered;
  uint unserved;
};
layout(std430, binding = BINDING_VIRTUAL_RENDER_LIST_SSBO) readonly buffer RenderList {
  ivec4 render_list[];  // x: level, yz: world page, w: pool page
};
layout(std430, binding = BINDING_VIRTUAL_COMMANDS_SSBO) buffer Commands { uint commands[]; };
layout(std430, binding = BINDING_VIRTUAL_DRAW_BOUNDS_SSBO) readonly buffer DrawBounds {
  vec4 draw_bounds[];  // lo, hi per draw
};
layout(std430, binding = BINDING_VIRTUAL_DRAW_PAGES_SSBO) writeonly buffer DrawPages {
  uint draw_pages[];
};

void main() {
  uint i = gl_GlobalInvocationID.x;
  uint draw = gl_GlobalInvocationID.y;
  if (i >= rendered) return;
  ivec4 page = render_list[i];
  GpuShadowView view = virtual_shadow.levels[page.x];
  vec3 lo = draw_bounds[2u * draw].xyz, hi = draw_bounds[2u * draw + 1u].xyz;
  vec2 box_lo = vec2(1e30), box_hi = vec2(-1e30);
  for (int c = 0; c < 8; ++c) {
    vec3 corner = vec3((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y,
                       (c & 4) != 0 ? hi.z : lo.z);
    vec2 p = (view.view * vec4(corner, 1.0)).xy;
    box_lo = min(box_lo, p);
    box_hi = max(box_hi, p);
  }
  float texel = view.depth_range.z;
  float size = texel * float(VIRTUAL_PAGE_TEXELS);
  vec2 page_lo = vec2(page.yz) * size - texel, page_hi = vec2(page.yz + 1) * size + texel;
  if (any(greaterThan(box_lo, page_hi)) || any(lessThan(box_hi, page_lo))) return;
  uint k = atomicAdd(commands[4u + 5u * draw + 1u], 1u);
  draw_pages[draw * uint(virtual_shadow.counts.z) + k] = i;
}
