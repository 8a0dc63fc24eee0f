// Summed-area table, pass 1: inclusive prefix sums along each row, in
// fixed point (see sat.glsl). One workgroup per row; the row is scanned in
// chunks of ROW_CHUNK texels (Hillis-Steele scan in shared memory), each
// chunk offset by the running total of the chunks before it.
#include "../shared/bindings.h"

#define ROW_CHUNK 256
layout(local_size_x = ROW_CHUNK) in;

layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2D source;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly uimage2D row_sums;
layout(location = 0) uniform float u_scale;

shared uvec4 scan[2][ROW_CHUNK];

void main() {
  const int width = textureSize(source, 0).x;
  const int y = int(gl_WorkGroupID.y);
  const int i = int(gl_LocalInvocationID.x);
  uvec4 carry = uvec4(0u);
  for (int start = 0; start < width; start += ROW_CHUNK) {
    const int x = start + i;
    vec4 v = x < width ? texelFetch(source, ivec2(x, y), 0) : vec4(0.0);
    scan[0][i] = uvec4(round(clamp(v, 0.0, 1.0) * u_scale));
    barrier();
    int from = 0;
    for (int offset = 1; offset < ROW_CHUNK; offset <<= 1) {
      uvec4 value = scan[from][i];
      if (i >= offset) value += scan[from][i - offset];
      scan[1 - from][i] = value;
      from = 1 - from;
      barrier();
    }
    uvec4 total = carry + scan[from][i];
    if (x < width) imageStore(row_sums, ivec2(x, y), total);
    carry += scan[from][ROW_CHUNK - 1];
    barrier();  // the next chunk overwrites scan[0]
  }
}
