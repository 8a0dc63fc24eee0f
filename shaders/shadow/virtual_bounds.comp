// Virtual shadow maps: the nearest and farthest z-bar of each 16 x 16
// texel cell of each page rendered this frame (8 x 8 cells a page), for
// backprojection's cut of the cone from a receiver to the source
// (shaders/shadow/virtual_shadow.glsl, after Guennebaud, Barthe and
// Paulin, Eurographics 2007). A cached page keeps its cells. Workgroup z
// is the page's place among the pages listed this frame: the
// orthographic levels' list first (render_list[0, rendered)), then the
// perspective (spot) levels' (render_list[pool pages, pool pages +
// rendered_written); virtual_allocate.comp). One group per pool page:
// each page is listed once.
#include "../shared/bindings.h"

layout(local_size_x = VIRTUAL_BOUNDS_CELLS, local_size_y = VIRTUAL_BOUNDS_CELLS) in;

layout(std430, binding = BINDING_VIRTUAL_COUNTERS_SSBO) readonly buffer Counters {
  // [2], [4]: the orthographic and the perspective pages listed this
  // frame (virtual_allocate.comp's rendered and rendered_written)
  uint counters[];
};
layout(std430, binding = BINDING_VIRTUAL_RENDER_LIST_SSBO) readonly buffer RenderList {
  ivec4 render_list[];  // x: level, yz: world page, w: pool page
};
layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray pool;
layout(rg32f, binding = IMAGE_OUTPUT) uniform writeonly image2DArray cells;

void main() {
  uint index = gl_WorkGroupID.z;
  if (index >= counters[2]) {
    index -= counters[2];
    if (index >= counters[4]) return;
    index += gl_NumWorkGroups.z;  // the perspective list starts at the pool's page count
  }
  int page = render_list[index].w;
  ivec2 cell = ivec2(gl_LocalInvocationID.xy);
  const int side = VIRTUAL_PAGE_TEXELS / VIRTUAL_BOUNDS_CELLS;
  vec2 bounds = vec2(1.0e30, -1.0e30);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      float d = texelFetch(pool, ivec3(cell * side + ivec2(x, y), page), 0).r;
      bounds = vec2(min(bounds.x, d), max(bounds.y, d));
    }
  }
  imageStore(cells, ivec3(cell, page), vec4(bounds, 0.0, 0.0));
}
