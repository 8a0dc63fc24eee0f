// One direction of the separable Gaussian blur (seed 001: 2W+1 weights
// beta * exp(-i^2 / (2 s^2)), s = W/2). Each workgroup filters a tile of
// TILE_ALONG x TILE_ACROSS texels: it stages the tile and its apron of
// RADIUS texels on either side in shared memory, so each texel is read from
// memory about (TILE_ALONG + 2 RADIUS) / TILE_ALONG times.
//
// Defines: AXIS (0: along x, 1: along y), RADIUS (W), IMAGE_FORMAT.
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
layout(std430, binding = BINDING_FILTER_WEIGHTS_SSBO) readonly buffer Weights {
  float weights[];  // 2 RADIUS + 1 of them, summing to 1
};

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
shared vec4 tile[TILE_ACROSS][LINE_STRIDE];

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

  for (int i = local.x; i < APRON; i += TILE_ALONG) {
    int a = clamp(group.x + i - RADIUS, 0, along_size - 1);
#if AXIS == 0
    tile[local.y][i] = texelFetch(source, ivec3(a, across, layer), 0);
#else
    tile[local.y][i] = texelFetch(source, ivec3(across, a, layer), 0);
#endif
  }
  barrier();

  const int along = group.x + local.x;
  if (along >= along_size || group.y + local.y >= across_size) return;
  vec4 sum = vec4(0.0);
  for (int k = 0; k <= 2 * RADIUS; ++k) sum += weights[k] * tile[local.y][local.x + k];
#if AXIS == 0
  imageStore(target, ivec3(along, across, layer), sum);
#else
  imageStore(target, ivec3(across, along, layer), sum);
#endif
}
