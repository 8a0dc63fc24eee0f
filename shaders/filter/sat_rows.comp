// Summed-area table, pass 1: inclusive prefix sums along each row, in
// fixed point (see sat.glsl). One thread per row walks along it, as the
// column pass walks down columns: no barriers, and each thread reads whole
// cache lines of its row in turn (a warp's 32 rows occupy 32 lines of L1
// at a time), so the pass stays near the bandwidth of a copy. On llvmpipe,
// where barriers are costly, it ran about three times faster than a
// workgroup-per-row Hillis-Steele scan (2.2x the copy against 12x, on a
// 1024^2 RGBA map). Workgroup y is the array layer (one shadow view).
#include "../shared/bindings.h"

layout(local_size_x = 64) in;

layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray source;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly uimage2DArray row_sums;
layout(location = 0) uniform float u_scale;

void main() {
  const ivec2 size = textureSize(source, 0).xy;
  const int layer = int(gl_WorkGroupID.y);
  const int y = int(gl_GlobalInvocationID.x);
  if (y >= size.y) return;
  uvec4 sum = uvec4(0u);
  for (int x = 0; x < size.x; ++x) {
    sum += uvec4(round(clamp(texelFetch(source, ivec3(x, y, layer), 0), 0.0, 1.0) * u_scale));
    imageStore(row_sums, ivec3(x, y, layer), sum);
  }
}
