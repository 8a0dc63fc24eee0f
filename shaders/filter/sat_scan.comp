// One direction of the summed-area table, in parallel: inclusive prefix
// sums along AXIS (0: rows, from the representation into the table; 1:
// columns, in place in the table). A workgroup scans SAT_TILE_ACROSS lines
// at once, walking along them a tile of SAT_TILE_ALONG texels at a time:
// each tile is scanned in shared memory (Hillis & Steele, "Data Parallel
// Algorithms", CACM 1986: log2 SAT_TILE_ALONG steps), and the carry, the
// line's sum up to the tile, added to it. The values are 32-bit
// fixed-point integers that wrap around, whose sums do not depend on the
// order they are added in: the table equals the one-thread-per-line scan
// (sat_rows.comp, sat_columns.comp) bit for bit.
//
// Defines: AXIS, IMAGE_FORMAT (the table's unsigned-integer format).
#include "../shared/bindings.h"
#include "../shared/filter_tiles.h"

#define TILE_ALONG SAT_TILE_ALONG
#define TILE_ACROSS SAT_TILE_ACROSS

// Threads adjacent in x read adjacent texels of a row: coalesced loads.
#if AXIS == 0
layout(local_size_x = TILE_ALONG, local_size_y = TILE_ACROSS) in;
layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray source;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly uimage2DArray table;
layout(location = 0) uniform float u_scale;  // the fixed-point scale 2^F
#else
layout(local_size_x = TILE_ACROSS, local_size_y = TILE_ALONG) in;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform uimage2DArray table;
#endif

// The tile being scanned, one entry per thread at its own invocation
// index (so threads adjacent in x use adjacent entries), and the carry of
// each line.
shared uvec4 tile[TILE_ALONG * TILE_ACROSS];
shared uvec4 carry[TILE_ACROSS];

void main() {
  const int layer = int(gl_WorkGroupID.z);
  const uint self = gl_LocalInvocationIndex;
#if AXIS == 0
  const ivec2 size = textureSize(source, 0).xy;
  const int along = int(gl_LocalInvocationID.x), across = int(gl_LocalInvocationID.y);
  const int along_size = size.x, across_size = size.y;
  const uint step = 1u;  // from a tile entry to the next one along the line
#else
  const ivec2 size = imageSize(table).xy;
  const int along = int(gl_LocalInvocationID.y), across = int(gl_LocalInvocationID.x);
  const int along_size = size.y, across_size = size.x;
  const uint step = uint(TILE_ACROSS);
#endif
  const int line = int(gl_WorkGroupID.x) * TILE_ACROSS + across;
  if (along == 0) carry[across] = uvec4(0u);

  for (int start = 0; start < along_size; start += TILE_ALONG) {
    const int a = start + along;
    const bool inside = line < across_size && a < along_size;
#if AXIS == 0
    const ivec3 p = ivec3(a, line, layer);
    // The same conversion as sat_rows.comp.
    const uvec4 value =
        inside ? uvec4(round(clamp(texelFetch(source, p, 0), 0.0, 1.0) * u_scale)) : uvec4(0u);
#else
    const ivec3 p = ivec3(line, a, layer);
    const uvec4 value = inside ? imageLoad(table, p) : uvec4(0u);
#endif
    tile[self] = value;
    barrier();
    for (int offset = 1; offset < TILE_ALONG; offset *= 2) {
      const uvec4 before = along >= offset ? tile[self - uint(offset) * step] : uvec4(0u);
      barrier();
      tile[self] += before;
      barrier();
    }
    const uvec4 sum = carry[across] + tile[self];
    if (inside) imageStore(table, p, sum);
    barrier();  // every thread has read the carry
    if (along == TILE_ALONG - 1) carry[across] = sum;
    barrier();
  }
}
