// Resolve and separable Gaussian in one pass (Peters, Münstermann,
// Wetzstein, Klein, "Non-Linearly Quantized Moment Shadow Maps", HPG 2017,
// sec. 5: the depth is read, turned into moments and filtered in shared
// memory, and the filtered moments are written once). The two-pass path
// writes the representation, reads it back with an apron for the
// horizontal blur, writes that, and reads it again for the vertical one;
// here only the depth (4 bytes a texel) is read, with its apron, and the
// filtered map is written once.
//
// Each workgroup filters a tile of TILE_X x TILE_Y texels of one layer:
//  1. stage: the tile's depths and an apron of RADIUS texels on every side
//     go to shared memory as representation_stage() values (one float a
//     texel: z-bar, or ESM's exponential);
//  2. horizontal: for every staged row, the 2 RADIUS + 1 taps of the
//     expanded representation (its moments) -> `rows`, TILE_X wide;
//  3. vertical: the 2 RADIUS + 1 rows of `rows` above and below each
//     texel, stored with representation_store().
// The weights are seed 001's Gaussian (gaussian_weights(), the two-pass
// blur's), and coordinates clamp to the border texel as there, so the
// result is the two-pass one up to the rounding of its intermediate maps.
//
// Shared memory is laid out so that the 32 threads of a row (a warp on
// NVIDIA hardware) always read 32 consecutive words: in step 2 along a
// staged row, in step 3 along a row of `rows` -- the vertical filter walks
// down rows of the tile, not down a column, so it has none of the two-pass
// vertical pass's strided reads. The staged rows are padded to an odd
// stride so that the flat staging loop, whose rows do not start at a
// multiple of 32, never maps two lanes onto one bank either.
//
// Defines: REPRESENTATION, MSM_QUANTIZED (shadow/representation.glsl),
// IMAGE_FORMAT, RADIUS (W, 1..16), TILE_Y (a multiple of GROUP_Y, chosen by
// the host so that the shared memory fits the device's limit).
#include "../shared/bindings.h"
#include "../shadow/representation.glsl"

#define TILE_X 32
#define GROUP_Y 8

layout(local_size_x = TILE_X, local_size_y = GROUP_Y) in;

layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray depth_map;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly image2DArray target;
layout(std430, binding = BINDING_FILTER_WEIGHTS_SSBO) readonly buffer Weights {
  float weights[];  // 2 RADIUS + 1 of them, summing to 1
};
layout(location = 0) uniform float u_esm_c;
layout(location = 1) uniform float u_evsm_positive;
layout(location = 2) uniform float u_evsm_negative;

#define SPAN_X (TILE_X + 2 * RADIUS)
#define SPAN_Y (TILE_Y + 2 * RADIUS)
#define STAGED_STRIDE (SPAN_X + 1 - SPAN_X % 2)  // odd: see above
shared STAGE_TYPE staged[SPAN_Y * STAGED_STRIDE];
shared REPRESENTATION_TYPE rows[SPAN_Y * TILE_X];

void main() {
  const RepresentationConstants constants =
      RepresentationConstants(u_esm_c, u_evsm_positive, u_evsm_negative);
  const ivec2 size = textureSize(depth_map, 0).xy;
  const int layer = int(gl_WorkGroupID.z);
  const ivec2 tile = ivec2(gl_WorkGroupID.xy) * ivec2(TILE_X, TILE_Y);
  const ivec2 local = ivec2(gl_LocalInvocationID.xy);
  const int thread = int(gl_LocalInvocationIndex);

  // 1. Stage the tile and its apron, clamped to the border texel.
  for (int i = thread; i < SPAN_X * SPAN_Y; i += TILE_X * GROUP_Y) {
    const ivec2 s = ivec2(i % SPAN_X, i / SPAN_X);
    const ivec2 p = clamp(tile + s - RADIUS, ivec2(0), size - 1);
    staged[s.y * STAGED_STRIDE + s.x] =
        representation_stage(texelFetch(depth_map, ivec3(p, layer), 0).r, constants);
  }
  barrier();

  // 2. Horizontal: every staged row, the tile's columns.
  for (int y = local.y; y < SPAN_Y; y += GROUP_Y) {
    REPRESENTATION_TYPE sum = REPRESENTATION_TYPE(0.0);
    for (int k = 0; k <= 2 * RADIUS; ++k) {
      sum += weights[k] * representation_expand(staged[y * STAGED_STRIDE + local.x + k], constants);
    }
    rows[y * TILE_X + local.x] = sum;
  }
  barrier();

  // 3. Vertical: the tile's texels.
  for (int y = local.y; y < TILE_Y; y += GROUP_Y) {
    const ivec2 p = tile + ivec2(local.x, y);
    if (any(greaterThanEqual(p, size))) continue;
    REPRESENTATION_TYPE sum = REPRESENTATION_TYPE(0.0);
    for (int k = 0; k <= 2 * RADIUS; ++k) sum += weights[k] * rows[(y + k) * TILE_X + local.x];
    imageStore(target, ivec3(p, layer), representation_store(sum));
  }
}
