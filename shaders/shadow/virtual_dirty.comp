// Virtual shadow maps: marks dirty the resident pages of level u_level
// whose world pages lie in [u_first, u_last] (a moved caster's old or new
// bounds), so the allocation lists them for rendering again.
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "virtual_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(location = 0) uniform int u_level;
layout(location = 1) uniform ivec2 u_first;
layout(location = 2) uniform ivec2 u_last;
layout(r32ui, binding = IMAGE_OUTPUT) uniform uimage2DArray page_table;

void main() {
  ivec2 page = u_first + ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThan(page, u_last))) return;
  imageAtomicOr(page_table, ivec3(virtual_page_slot(page), u_level), PAGE_DIRTY);
}
