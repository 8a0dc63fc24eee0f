// Virtual shadow maps, marking: for each pixel the camera sees (its
// depth buffer; CameraDepthBuffer), the pages of its level
// (virtual_level()) that its lookup reads, PAGE_REQUESTED in the page
// table. The lookup reads around its texel: the normal offset, the
// filter's window, the bilinear taps (virtual_shadow.params.y texels in
// all), so the marked square is widened by as much.
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "lookup.glsl"
#include "virtual_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(location = 0) uniform mat4 u_inverse_view_projection;  // NDC -> world
layout(location = 1) uniform ivec2 u_size;                    // the depth buffer's pixels
layout(location = 2) uniform int u_zero_to_one;  // clip control GL_ZERO_TO_ONE: NDC z = depth
layout(location = 3) uniform float u_background;  // the depth of pixels that see nothing

layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D camera_depth;
layout(r32ui, binding = IMAGE_OUTPUT) uniform uimage2DArray page_table;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, u_size))) return;
  float depth = texelFetch(camera_depth, pixel, 0).r;
  if (depth == u_background) return;
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(u_size) * 2.0 - 1.0;
  float ndc_z = u_zero_to_one != 0 ? depth : 2.0 * depth - 1.0;
  vec4 p = u_inverse_view_projection * vec4(ndc, ndc_z, 1.0);
  vec3 world = p.xyz / p.w;
  int level = virtual_level(world);
  vec2 texel = shadow_map_uv(virtual_shadow.levels[level], world) * float(VIRTUAL_TEXELS);
  float reach = virtual_shadow.params.y;
  ivec2 first = clamp(ivec2(floor((texel - reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0),
                      ivec2(VIRTUAL_PAGES - 1));
  ivec2 last = clamp(ivec2(floor((texel + reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0),
                     ivec2(VIRTUAL_PAGES - 1));
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
