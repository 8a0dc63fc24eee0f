// One direction of the separable Gaussian blur (seed 001: 2W+1 weights
// beta * exp(-i^2 / (2 s^2)), s = W/2). Each workgroup filters a tile of
// TILE_ALONG x TILE_ACROSS texels: it stages the tile and its apron of
// RADIUS texels on either side in shared memory, so each texel is read from
// memory about (TILE_ALONG + 2 RADIUS) / TILE_ALONG times.
//
// On a CPU rasterizer (llvmpipe) the tile in shared memory costs more than
// it saves: there a barrier switches between coroutines and each lane's
// shared load is a scalar one, so every tap reads the source instead
// (STAGE_IN_SHARED_MEMORY 0): 2048^2, W = 32, 5.5 times less CPU time.
// There each invocation filters a run of FILTER_DIRECT_RUN texels along
// the axis (shared/filter_tiles.h) from one read of their window
// (FILTER_DIRECT_RUN + 2 RADIUS reads for the run instead of 2 RADIUS + 1
// for each texel). The same texels are summed in the same order with the
// same weights: both variants give the same floats.
//
// Defines: AXIS (0: along x, 1: along y), RADIUS (W), GAUSSIAN_WEIGHTS (the
// 2 RADIUS + 1 weights, comma-separated), IMAGE_FORMAT,
// STAGE_IN_SHARED_MEMORY (1: the tile in shared memory, 0: every tap read
// from the source).
// Coordinates clamp to the border texel: nothing from outside the map is
// mixed in. Each layer of the array (one shadow view) is filtered on its
// own: workgroup z is the layer, so no view bleeds into another.
#include "../shared/bindings.h"
#include "../shared/filter_tiles.h"

#define TILE_ALONG GAUSSIAN_TILE_ALONG
#define TILE_ACROSS GAUSSIAN_TILE_ACROSS

#if AXIS == 0
layout(local_size_x = TILE_ALONG, local_size_y = TILE_ACROSS) in;
#else
// Threads adjacent in x read adjacent texels of a row: coalesced loads.
layout(local_size_x = TILE_ACROSS, local_size_y = TILE_ALONG) in;
#endif

layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray source;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly image2DArray target;
// The first layer of the run this dispatch blurs (filter/layer_runs.hpp).
layout(location = 0) uniform int u_first_layer;
// The 2 RADIUS + 1 weights, summing to 1, as compile-time constants
// (gaussian_weight_list(): the floats themselves); read from a buffer per
// tap, the loop ran about three times slower on llvmpipe.
const float weights[2 * RADIUS + 1] = float[](GAUSSIAN_WEIGHTS);

#define APRON (TILE_ALONG + 2 * RADIUS)
// Each of the TILE_ACROSS lines of the tile is stored APRON | 1 entries
// apart: an odd stride. The vertical pass's neighbouring threads (adjacent
// in x) sit on different lines at the same position along them; with an
// even stride such as APRON = 64 + 2 RADIUS for RADIUS a multiple of 4 the
// 8 threads that share a 16-byte load cycle would hit the same banks
// (an 8-way conflict on NVIDIA's 32 banks of 4 bytes); with an odd one
// they hit 8 different ones. The horizontal pass's neighbours read along
// one line, which an odd stride does not change.
#define LINE_STRIDE (APRON | 1)
#if STAGE_IN_SHARED_MEMORY
shared vec4 tile[TILE_ACROSS][LINE_STRIDE];
#endif

// The source's texel `a` along the pass's axis, on line `across`.
vec4 source_texel(int a, int across, int layer) {
#if AXIS == 0
  return texelFetch(source, ivec3(a, across, layer), 0);
#else
  return texelFetch(source, ivec3(across, a, layer), 0);
#endif
}

// Writes the filtered texel `a` along the pass's axis, on line `across`.
void store_texel(int a, int across, int layer, vec4 value) {
#if AXIS == 0
  imageStore(target, ivec3(a, across, layer), value);
#else
  imageStore(target, ivec3(across, a, layer), value);
#endif
}

void main() {
  const ivec2 size = textureSize(source, 0).xy;
  const int layer = u_first_layer + int(gl_WorkGroupID.z);
#if AXIS == 0
  const ivec2 local = ivec2(gl_LocalInvocationID.xy);     // (along, across)
  const ivec2 group = ivec2(gl_WorkGroupID.xy) * ivec2(TILE_ALONG, TILE_ACROSS);
  const int along_size = size.x;
  const int across_size = size.y;
#else
  const ivec2 local = ivec2(gl_LocalInvocationID.yx);
  const ivec2 group = ivec2(gl_WorkGroupID.yx) * ivec2(TILE_ALONG, TILE_ACROSS);
  const int along_size = size.y;
  const int across_size = size.x;
#endif
  const int across = min(group.y + local.y, across_size - 1);

#if STAGE_IN_SHARED_MEMORY
  for (int i = local.x; i < APRON; i += TILE_ALONG) {
    tile[local.y][i] = source_texel(clamp(group.x + i - RADIUS, 0, along_size - 1), across, layer);
  }
  barrier();
#endif

#if STAGE_IN_SHARED_MEMORY
  const int along = group.x + local.x;
  if (along >= along_size || group.y + local.y >= across_size) return;
  vec4 sum = vec4(0.0);
  for (int k = 0; k <= 2 * RADIUS; ++k) sum += weights[k] * tile[local.y][local.x + k];
  store_texel(along, across, layer, sum);
#else
  // FILTER_DIRECT_RUN consecutive texels along the axis, each source texel of
  // their window read once for all of them; each sum takes its taps in the
  // tile's order (k = 0 .. 2 RADIUS).
  const int along = (group.x + local.x) * FILTER_DIRECT_RUN;
  if (along >= along_size || group.y + local.y >= across_size) return;
  vec4 sums[FILTER_DIRECT_RUN];
  for (int r = 0; r < FILTER_DIRECT_RUN; ++r) sums[r] = vec4(0.0);
  for (int j = 0; j < FILTER_DIRECT_RUN + 2 * RADIUS; ++j) {
    const vec4 v = source_texel(clamp(along + j - RADIUS, 0, along_size - 1), across, layer);
    for (int r = 0; r < FILTER_DIRECT_RUN; ++r) {  // constant bounds: unrolled, sums in registers
      const int k = j - r;
      if (k >= 0 && k <= 2 * RADIUS) sums[r] += weights[k] * v;
    }
  }
  // Past the map's end a store does nothing (an image's rules).
  for (int r = 0; r < FILTER_DIRECT_RUN; ++r) store_texel(along + r, across, layer, sums[r]);
#endif
}
