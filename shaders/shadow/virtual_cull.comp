// Virtual shadow maps, per-page caster culling: one thread per (listed
// page, caster draw), over both lists (x below the pool's page count: the
// orthographic levels' pages, render_list[x]; above: the perspective
// levels', render_list[x] from the pool's page count). A draw is listed
// for a page only where its world bounds, seen from the light (the box's
// eight corners in the level's light frame, or projected by a spot
// level's view; a box reaching behind a spot's eye covers every page),
// cover the page's square widened by one texel (the margin
// virtual_pages_of_box() gives a moved caster, for the filters' taps at
// the page's edge). Its command's instance count is the number of pages
// listed; draw_pages[(list * draws + d) * pool pages + i] is instance i's
// index into the render list (virtual_page.vert reads it).
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "virtual_lookup.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = BINDING_VIRTUAL_COUNTERS_SSBO) readonly buffer Counters {
  uint free_count;
  uint taken;
  uint rendered;
  uint unserved;
  uint rendered_written;  // perspective pages listed
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
  uint pool = uint(virtual_shadow.counts.z);
  uint x = gl_GlobalInvocationID.x;
  uint draw = gl_GlobalInvocationID.y;
  uint list = x >= pool ? 1u : 0u;
  uint i = x - list * pool;
  if (i >= (list == 0u ? rendered : rendered_written)) return;
  ivec4 page = render_list[x];
  GpuShadowView view = virtual_shadow.levels[page.x];
  vec3 lo = draw_bounds[2u * draw].xyz, hi = draw_bounds[2u * draw + 1u].xyz;
  // The box's footprint in the level's texels.
  vec2 box_lo = vec2(1e30), box_hi = vec2(-1e30);
  float texels = float(virtual_level_texels(page.x));
  bool everywhere = false;
  for (int c = 0; c < 8; ++c) {
    vec3 corner = vec3((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y,
                       (c & 4) != 0 ? hi.z : lo.z);
    vec2 p;
    if (view.perspective != 0) {
      vec4 clip = view.view_projection * vec4(corner, 1.0);
      if (clip.w <= 0.0) {
        everywhere = true;
        break;
      }
      p = (clip.xy / clip.w * 0.5 + 0.5) * texels;
    } else {
      p = (view.view * vec4(corner, 1.0)).xy / view.depth_range.z;
    }
    box_lo = min(box_lo, p);
    box_hi = max(box_hi, p);
  }
  vec2 page_lo = vec2(page.yz) * float(VIRTUAL_PAGE_TEXELS) - 1.0;
  vec2 page_hi = vec2(page.yz + 1) * float(VIRTUAL_PAGE_TEXELS) + 1.0;
  if (!everywhere && (any(greaterThan(box_lo, page_hi)) || any(lessThan(box_hi, page_lo)))) return;
  uint list_draw = list * uint(virtual_shadow.counts.w) + draw;
  uint k = atomicAdd(commands[8u + 5u * list_draw + 1u], 1u);
  draw_pages[list_draw * pool + k] = x;
}
