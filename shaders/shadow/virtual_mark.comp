// Virtual shadow maps, marking: for each pixel the camera sees, the pages
// its lookup reads under each level bias (virtual_level_biased(), bias k:
// PAGE_WANTED(k)) in the page table; the allocation then keeps the finest
// bias that fits the pool. The lookup reads around its texel: the normal
// offset, the filter's window, the bilinear taps (virtual_shadow.params.y
// texels in all), so the marked square is widened by as much.
#include "../common/uniforms.glsl"
#include "../common/world_position.glsl"
#include "lookup.glsl"
#include "virtual_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gbuffer_depth;
layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gbuffer_normal;
// The triangle's normal: the one the lookup picks its level with.
layout(binding = UNIT_GBUFFER_FACET) uniform sampler2D gbuffer_facet;
layout(r32ui, binding = IMAGE_OUTPUT) uniform uimage2DArray page_table;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(frame.viewport.xy)))) return;
  // Shininess 0 marks the background, as in lighting.frag.
  if (texelFetch(gbuffer_normal, pixel, 0).w == 0.0) return;
  vec3 world = world_position(pixel, texelFetch(gbuffer_depth, pixel, 0).r);
  vec3 normal = normalize(texelFetch(gbuffer_facet, pixel, 0).xyz);
  float reach = virtual_shadow.params.y;
  for (int bias = 0; bias < VIRTUAL_LEVEL_BIASES; ++bias) {
    int level = virtual_level_biased(world, normal, bias);
    uint wanted = PAGE_WANTED(bias);
    vec2 texel = shadow_map_uv(virtual_shadow.levels[level], world) * float(VIRTUAL_TEXELS);
    ivec2 first = clamp(ivec2(floor((texel - reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0),
                        ivec2(VIRTUAL_PAGES - 1));
    ivec2 last = clamp(ivec2(floor((texel + reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0),
                       ivec2(VIRTUAL_PAGES - 1));
    for (int y = first.y; y <= last.y; ++y) {
      for (int x = first.x; x <= last.x; ++x) {
        ivec3 entry = ivec3(virtual_level_slot(level, ivec2(x, y)), level);
        // Most neighbours ask for the same page: an atomic only for the first.
        if ((imageLoad(page_table, entry).r & wanted) == 0u) {
          imageAtomicOr(page_table, entry, wanted);
        }
      }
    }
  }
}
