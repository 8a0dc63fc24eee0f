// One direction of the summed-area table, in parallel: inclusive prefix
// sums along AXIS (0: rows, from the representation into the table; 1:
// columns, in place in the table). A workgroup scans SAT_TILE_ACROSS lines
// at once, walking along them a tile of SAT_TILE_ALONG texels at a time,
// with a raking scan (Blelloch, "Prefix Sums and Their Applications",
// 1990, sec. 1.5: one processor per run of elements; Merrill & Grimshaw's
// "raking" reduce-then-scan): each of a line's SAT_THREADS_ALONG threads
// sums its run of SAT_RUN consecutive texels in registers, adds the runs
// before its own (a handful of shared reads), and writes its run's
// inclusive sums. Four barriers a tile of SAT_TILE_ALONG texels (0.03 a
// texel), where a Hillis-Steele scan of the tile (Hillis & Steele, CACM
// 1986) took two for each of its log2(tile) steps plus three (0.4 a texel
// for 32-texel tiles). Loads and stores go through shared memory so that
// adjacent threads touch adjacent texels (coalesced); the runs are padded
// by one entry, so a line's threads reading their runs in step do not
// fall on one bank. The values are 32-bit fixed-point integers that wrap
// around, whose sums do not depend on the order they are added in: the
// table equals the one-thread-per-line scan (sat_rows.comp,
// sat_columns.comp) bit for bit.
//
// Defines: AXIS, IMAGE_FORMAT (the table's unsigned-integer format).
#include "../shared/bindings.h"
#include "../shared/filter_tiles.h"

#define THREADS_ALONG SAT_THREADS_ALONG
#define RUN SAT_RUN
#define TILE_ALONG SAT_TILE_ALONG
#define TILE_ACROSS SAT_TILE_ACROSS
#define LINE_STRIDE (TILE_ALONG + THREADS_ALONG)  // a line's entries, one pad a run

// Threads adjacent in x read adjacent texels: coalesced loads.
#if AXIS == 0
layout(local_size_x = THREADS_ALONG, local_size_y = TILE_ACROSS) in;
layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray source;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly uimage2DArray table;
layout(location = 0) uniform float u_scale;  // the fixed-point scale 2^F
#else
layout(local_size_x = TILE_ACROSS, local_size_y = THREADS_ALONG) in;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform uimage2DArray table;
#endif

// The tile being scanned, line by line, and each run's sum.
shared uvec4 tile[TILE_ACROSS * LINE_STRIDE];
shared uvec4 run_sums[TILE_ACROSS * THREADS_ALONG];

// Shared-memory entry of texel e (0..TILE_ALONG-1) of the tile's line.
int entry(int line_base, int e) {
  return line_base + e + e / RUN;
}

void main() {
  const int layer = int(gl_WorkGroupID.z);
#if AXIS == 0
  const ivec2 size = textureSize(source, 0).xy;
  const int along = int(gl_LocalInvocationID.x), across = int(gl_LocalInvocationID.y);
  const int along_size = size.x, across_size = size.y;
#else
  const ivec2 size = imageSize(table).xy;
  const int along = int(gl_LocalInvocationID.y), across = int(gl_LocalInvocationID.x);
  const int along_size = size.y, across_size = size.x;
#endif
  const int line = int(gl_WorkGroupID.x) * TILE_ACROSS + across;
  const int line_base = across * LINE_STRIDE;
  const int first = along * RUN;  // this thread's run
  uvec4 carry = uvec4(0u);        // the line's sum before the tile

  for (int start = 0; start < along_size; start += TILE_ALONG) {
    // 1. Load the tile, adjacent threads taking adjacent texels.
    for (int j = 0; j < RUN; ++j) {
      const int e = j * THREADS_ALONG + along;
      const int a = start + e;
      const bool inside = line < across_size && a < along_size;
#if AXIS == 0
      // The same conversion as sat_rows.comp.
      const uvec4 value =
          inside ? uvec4(round(clamp(texelFetch(source, ivec3(a, line, layer), 0), 0.0, 1.0) *
                               u_scale))
                 : uvec4(0u);
#else
      const uvec4 value = inside ? imageLoad(table, ivec3(line, a, layer)) : uvec4(0u);
#endif
      tile[entry(line_base, e)] = value;
    }
    barrier();
    // 2. Each thread sums its run.
    uvec4 run = uvec4(0u);
    for (int j = 0; j < RUN; ++j) run += tile[entry(line_base, first + j)];
    run_sums[across * THREADS_ALONG + along] = run;
    barrier();
    // 3. The runs before this one, and the whole tile for the next carry.
    uvec4 sum = carry, tile_sum = uvec4(0u);
    for (int t = 0; t < THREADS_ALONG; ++t) {
      const uvec4 s = run_sums[across * THREADS_ALONG + t];
      if (t < along) sum += s;
      tile_sum += s;
    }
    carry += tile_sum;
    // 4. The run's inclusive sums.
    for (int j = 0; j < RUN; ++j) {
      const int i = entry(line_base, first + j);
      sum += tile[i];
      tile[i] = sum;
    }
    barrier();
    // 5. Store, adjacent threads taking adjacent texels.
    for (int j = 0; j < RUN; ++j) {
      const int e = j * THREADS_ALONG + along;
      const int a = start + e;
      if (line < across_size && a < along_size) {
#if AXIS == 0
        imageStore(table, ivec3(a, line, layer), tile[entry(line_base, e)]);
#else
        imageStore(table, ivec3(line, a, layer), tile[entry(line_base, e)]);
#endif
      }
    }
    barrier();  // every thread has stored its texels before the next tile is loaded
  }
}
