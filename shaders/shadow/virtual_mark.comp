// Virtual shadow maps, marking: for each pixel the camera sees and each
// light with virtual maps, the pages of its level (virtual_level()) that
// its lookup reads, PAGE_REQUESTED in the page table. The lookup reads
// around its texel: the normal offset, the filter's window, the bilinear
// taps (virtual_shadow.params.y texels in all), so the marked square is
// widened by as much.
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
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (virtual_shadow.lights[i].y == 0) continue;
    int level = virtual_level(i, world);
    GpuShadowView view = virtual_shadow.levels[level];
    vec4 clip = view.view_projection * vec4(world, 1.0);
    // A spot map holds nothing for points outside its frustum (they are
    // lit: shadow_lookup()'s `inside`).
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (view.perspective != 0 &&
        (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))) {
      continue;
    }
    int texels = virtual_level_texels(level);
    vec2 texel = uv * float(texels);
    float reach = virtual_shadow.params.y;
    ivec2 last_page = ivec2(texels / VIRTUAL_PAGE_TEXELS - 1);
    ivec2 first =
        clamp(ivec2(floor((texel - reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0), last_page);
    ivec2 last =
        clamp(ivec2(floor((texel + reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0), last_page);
    for (int y = first.y; y <= last.y; ++y) {
      for (int x = first.x; x <= last.x; ++x) {
        ivec3 entry = ivec3(virtual_level_slot(level, ivec2(x, y)), level);
        // Most neighbours ask for the same page: an atomic only for the first.
        if ((imageLoad(page_table, entry).r & PAGE_REQUESTED) == 0u) {
          imageAtomicOr(page_table, entry, PAGE_REQUESTED);
        }
      }
    }
  }
}
