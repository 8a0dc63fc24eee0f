// Summed-area table, pass 2: inclusive prefix sums down each column, in
// place. One thread per column walks down it; threads adjacent in x touch
// adjacent texels, so every load and store is coalesced. Workgroup y is
// the array layer (one shadow view).
#include "../shared/bindings.h"

layout(local_size_x = 64) in;

layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform uimage2DArray table;

void main() {
  const ivec2 size = imageSize(table).xy;
  const int layer = int(gl_WorkGroupID.y);
  const int x = int(gl_GlobalInvocationID.x);
  if (x >= size.x) return;
  uvec4 sum = uvec4(0u);
  for (int y = 0; y < size.y; ++y) {
    sum += imageLoad(table, ivec3(x, y, layer));
    imageStore(table, ivec3(x, y, layer), sum);
  }
}
