// Virtual shadow maps, marking: for each pixel the camera sees and each
// light with virtual maps, the pages its lookup reads under each level
// bias (virtual_level_biased(), bias k: PAGE_WANTED(k)) in the page table;
// the allocation then keeps the finest bias whose pages fit the pool. The
// lookup reads around its texel: the normal offset, the filter's window,
// the bilinear taps (virtual_shadow.params.y texels in all), so the marked
// square is widened by as much; PCSS's and backprojection's windows also
// at the coarser levels they read them from.
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
  // PCSS and backprojection (params.w: their window, in texels) read the
  // source's search region at the levels from the receiver's up to the one
  // where it fits the window (virtual_search_level()).
  float window = virtual_shadow.params.w;
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (virtual_shadow.lights[i].y == 0) continue;
    for (int bias = 0; bias < VIRTUAL_LEVEL_BIASES; ++bias) {
      int level = virtual_level_biased(i, world, normal, bias);
      int last_level = window > 0.0 ? virtual_search_level(i, level, world, window) : level;
      uint wanted = PAGE_WANTED(bias);
      for (int l = level; l <= last_level; ++l) {
        GpuShadowView view = virtual_shadow.levels[l];
        vec4 clip = view.view_projection * vec4(world, 1.0);
        // A spot map holds nothing for points outside its frustum (they are
        // lit: shadow_lookup()'s `inside`).
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        if (view.perspective != 0 &&
            (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))) {
          break;
        }
        int texels = virtual_level_texels(l);
        vec2 texel = uv * float(texels);
        float reach = virtual_shadow.params.y;
        if (window > 0.0) reach += 0.5 * min(virtual_search_texels(level, l, world), window);
        ivec2 last_page = ivec2(texels / VIRTUAL_PAGE_TEXELS - 1);
        ivec2 first =
            clamp(ivec2(floor((texel - reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0), last_page);
        ivec2 last =
            clamp(ivec2(floor((texel + reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0), last_page);
        for (int y = first.y; y <= last.y; ++y) {
          for (int x = first.x; x <= last.x; ++x) {
            ivec3 entry = ivec3(virtual_level_slot(l, ivec2(x, y)), l);
            // Most neighbours ask for the same page: an atomic only for the first.
            if ((imageLoad(page_table, entry).r & wanted) == 0u) {
              imageAtomicOr(page_table, entry, wanted);
            }
          }
        }
      }
    }
  }
}
