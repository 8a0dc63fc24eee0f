// Virtual shadow maps, marking: for each pixel the camera sees, the pages
// of its level (virtual_level()) that its lookup reads, PAGE_REQUESTED in
// the page table. The lookup reads around its texel: the normal offset,
// the filter's window, the bilinear taps (virtual_shadow.params.y texels
// in all), so the marked square is widened by as much; PCSS's and
// backprojection's windows also at the coarser levels they read them from.
#include "../common/uniforms.glsl"
#include "../common/world_position.glsl"
#include "lookup.glsl"
#include "virtual_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gbuffer_depth;
layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gbuffer_normal;
layout(r32ui, binding = IMAGE_OUTPUT) uniform uimage2DArray page_table;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(frame.viewport.xy)))) return;
  // Shininess 0 marks the background, as in lighting.frag.
  if (texelFetch(gbuffer_normal, pixel, 0).w == 0.0) return;
  vec3 world = world_position(pixel, texelFetch(gbuffer_depth, pixel, 0).r);
  // PCSS and backprojection (params.z: their window, in texels) read the
  // source's search region at the levels from the receiver's up to the
  // one where it fits the window (virtual_search_level()).
  int level = virtual_level(world);
  float window = virtual_shadow.params.z;
  int last_level = window > 0.0 ? virtual_search_level(level, world, window) : level;
  for (int l = level; l <= last_level; ++l) {
    vec2 texel = shadow_map_uv(virtual_shadow.levels[l], world) * float(VIRTUAL_TEXELS);
    float reach = virtual_shadow.params.y;
    if (window > 0.0) {
      float search = virtual_search_world(l, world) / virtual_shadow.levels[l].depth_range.z;
      reach += 0.5 * min(search, window);
    }
    ivec2 first = clamp(ivec2(floor((texel - reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0),
                        ivec2(VIRTUAL_PAGES - 1));
    ivec2 last = clamp(ivec2(floor((texel + reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0),
                       ivec2(VIRTUAL_PAGES - 1));
    for (int y = first.y; y <= last.y; ++y) {
      for (int x = first.x; x <= last.x; ++x) {
        ivec3 entry = ivec3(virtual_level_slot(l, ivec2(x, y)), l);
        // Most neighbours ask for the same page: an atomic only for the first.
        if ((imageLoad(page_table, entry).r & PAGE_REQUESTED) == 0u) {
          imageAtomicOr(page_table, entry, PAGE_REQUESTED);
        }
      }
    }
  }
}
