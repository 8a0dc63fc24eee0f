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
//     texel: z-bar, or the exponential of ESM and EVSM2; EVSM4's two warps
//     where they fit, EVSM4_STAGE_WARPS, so no tap takes an exponential);
//  2. horizontal: for every staged row, the 2 RADIUS + 1 taps of the
//     expanded representation (its moments) -> `rows`, TILE_X wide;
//  3. vertical: the 2 RADIUS + 1 rows of `rows` above and below each
//     texel, stored with representation_store(); each thread filters
//     ROWS_PER_THREAD consecutive texels of a column at once.
// Measured on llvmpipe (1024^2 msm16 maps, W = 4, `penumbra bench --sweep
// fused`): 401 ms against 938 ms for the resolve and the two blur passes;
// the tap loops with the weights as run-time data took 1258 ms, and step 3
// one texel per thread 752 ms.
// The weights are seed 001's Gaussian (gaussian_weights(), the two-pass
// blur's), and coordinates clamp to the border texel as there, so the
// result is the two-pass one up to the rounding of its intermediate maps.
//
// Shared memory is laid out so that the 32 threads of a row (a warp on
// NVIDIA hardware) always read 32 consecutive words at once: in step 2
// along a staged row, in step 3 along a row of `rows` (a thread's several
// texels lie down its column, its neighbours' in the next columns) -- the
// vertical filter walks down rows of the tile, not down a column, so it has
// none of the two-pass vertical pass's 8-way bank conflicts. The staged
// rows are padded to an odd stride, so that the flat staging loop, whose
// rows do not start at a multiple of 32, never maps two lanes onto one bank
// either.
//
// SAMPLES above 1 (--shadow-msaa): the depth maps are multisampled, and
// step 1 stages each texel's mean of its samples' expanded representation
// (as filter/resolve.comp stores it) instead of one value to expand: the
// moments of different depths do not combine into one staged value. The
// staged rows then take the representation's channels, which is why the
// host allows four-moment techniques a narrower radius here
// (max_fused_blur()).
//
// On a CPU rasterizer (llvmpipe) shared memory costs more than it saves,
// as in filter/gaussian_blur.comp (a barrier switches coroutines, each
// lane's shared load is a scalar one), and the tile is short there (32 KiB
// give 8 rows at W = 16, so step 2 filters five rows for every one it
// keeps). There (STAGE_IN_SHARED_MEMORY 0) steps 2 and 3 run as two
// dispatches, PASS 1 and PASS 2, a band of rows of a layer at a time,
// through a float map of the band and its apron, `rows` as a texture (a
// few MB, not a layer's 64). Each invocation filters a run of
// FILTER_DIRECT_RUN texels (shared/filter_tiles.h), along a row in PASS 1
// and down a column in PASS 2, and reads and expands each texel of the
// run's window once: FILTER_DIRECT_RUN + 2 RADIUS reads for the run
// instead of 2 RADIUS + 1 for each texel. The same taps are summed in the
// same order with the same weights as in the tile; where a value serves
// several sums the compiler may keep a multiply and an add apart that it
// fuses in the tile, so the maps agree to rounding
// (FusedFilterStagingsAgreeToRounding). llvmpipe, msm, 2048^2, W = 16:
// 5.1 s for the whole render with the tile, 0.9 s with two dispatches of
// one texel an invocation; W = 4, one layer (`bench --light spot --blur
// 4`): esm 100 -> 38 ms, msm 114 -> 66 ms with runs of 4 texels.
//
// Defines: REPRESENTATION, MSM_QUANTIZED, EVSM4_STAGE_WARPS (shadow/
// representation.glsl), IMAGE_FORMAT, RADIUS (W, 1..16), GAUSSIAN_WEIGHTS
// (the weights, comma-separated), TILE_Y (a multiple of GROUP_Y, chosen by the host so that the
// shared memory fits the device's limit), SAMPLES (1, 2, 4, 8),
// STAGE_IN_SHARED_MEMORY (1: the tile, one pass; 0: PASS 1 or 2, and
// ROWS_FORMAT, the float image format of the rows between them).
#include "../shared/bindings.h"
#include "../shared/filter_tiles.h"
#include "../shadow/representation.glsl"

#ifndef SAMPLES
#define SAMPLES 1
#endif
#ifndef STAGE_IN_SHARED_MEMORY
#define STAGE_IN_SHARED_MEMORY 1
#endif

#define TILE_X 32
#define GROUP_Y 8
#define ROWS_PER_THREAD (TILE_Y / GROUP_Y)

layout(local_size_x = TILE_X, local_size_y = GROUP_Y) in;

#if SAMPLES > 1
#define STAGED_TYPE REPRESENTATION_TYPE
#else
#define STAGED_TYPE STAGE_TYPE
#endif
#if STAGE_IN_SHARED_MEMORY || PASS == 1
#if SAMPLES > 1
layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DMSArray depth_map;
#else
layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray depth_map;
#endif
#else
// PASS 2: step 2's rows of the layer being filtered.
layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray rows_map;
#endif
#if !STAGE_IN_SHARED_MEMORY && PASS == 1
layout(ROWS_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly image2DArray rows_image;
#else
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly image2DArray target;
#endif
// The 2 RADIUS + 1 weights, summing to 1, as compile-time constants (printed
// exactly by the host): the tap loops unroll with them folded in, and the
// symmetric pairs share one multiply.
const float weights[2 * RADIUS + 1] = float[](GAUSSIAN_WEIGHTS);
layout(location = 0) uniform float u_esm_c;
layout(location = 1) uniform float u_evsm_positive;
layout(location = 2) uniform float u_evsm_negative;
// The first layer of the run this dispatch filters (filter/layer_runs.hpp).
layout(location = 3) uniform int u_first_layer;
#if !STAGE_IN_SHARED_MEMORY
// The direct passes filter a layer in bands of rows: the texel rows this
// dispatch computes, [x, y), and the texel row that the rows' first holds.
layout(location = 4) uniform ivec3 u_rows;
#endif

#if STAGE_IN_SHARED_MEMORY
#define SPAN_X (TILE_X + 2 * RADIUS)
#define SPAN_Y (TILE_Y + 2 * RADIUS)
#define STAGED_STRIDE (SPAN_X + 1 - SPAN_X % 2)  // odd: see above
shared STAGED_TYPE staged[SPAN_Y * STAGED_STRIDE];
shared REPRESENTATION_TYPE rows[SPAN_Y * TILE_X];
#endif

#if STAGE_IN_SHARED_MEMORY || PASS == 1
// What step 1 keeps of texel p: its stage value, or with several samples
// the mean of their expanded representations.
STAGED_TYPE staged_texel(ivec3 p, RepresentationConstants constants) {
#if SAMPLES > 1
  REPRESENTATION_TYPE sum = REPRESENTATION_TYPE(0.0);
  for (int i = 0; i < SAMPLES; ++i) {
    sum += representation_expand(representation_stage(texelFetch(depth_map, p, i).r, constants),
                                 constants);
  }
  return sum * (1.0 / float(SAMPLES));
#else
  return representation_stage(texelFetch(depth_map, p, 0).r, constants);
#endif
}

// The values step 2 filters from a staged texel.
REPRESENTATION_TYPE staged_expand(STAGED_TYPE s, RepresentationConstants constants) {
#if SAMPLES > 1
  return s;
#else
  return representation_expand(s, constants);
#endif
}

#endif

#if STAGE_IN_SHARED_MEMORY
void main() {
  const RepresentationConstants constants =
      RepresentationConstants(u_esm_c, u_evsm_positive, u_evsm_negative);
#if SAMPLES > 1
  const ivec2 size = textureSize(depth_map).xy;
#else
  const ivec2 size = textureSize(depth_map, 0).xy;
#endif
  const int layer = u_first_layer + int(gl_WorkGroupID.z);
  const ivec2 tile = ivec2(gl_WorkGroupID.xy) * ivec2(TILE_X, TILE_Y);
  const ivec2 local = ivec2(gl_LocalInvocationID.xy);
  const int thread = int(gl_LocalInvocationIndex);

  // 1. Stage the tile and its apron, clamped to the border texel.
  for (int i = thread; i < SPAN_X * SPAN_Y; i += TILE_X * GROUP_Y) {
    const ivec2 s = ivec2(i % SPAN_X, i / SPAN_X);
    const ivec2 p = clamp(tile + s - RADIUS, ivec2(0), size - 1);
    staged[s.y * STAGED_STRIDE + s.x] = staged_texel(ivec3(p, layer), constants);
  }
  barrier();

  // 2. Horizontal: every staged row, the tile's columns.
  for (int y = local.y; y < SPAN_Y; y += GROUP_Y) {
    const int c = y * STAGED_STRIDE + local.x + RADIUS;  // the centre tap
    REPRESENTATION_TYPE sum = weights[RADIUS] * staged_expand(staged[c], constants);
    for (int k = 1; k <= RADIUS; ++k) {
      sum += weights[RADIUS + k] *
             (staged_expand(staged[c - k], constants) + staged_expand(staged[c + k], constants));
    }
    rows[y * TILE_X + local.x] = sum;
  }
  barrier();

  // 3. Vertical: each thread filters ROWS_PER_THREAD consecutive texels of
  // its column, so each row of `rows` it reads serves up to that many of
  // them: ROWS_PER_THREAD + 2 RADIUS loads instead of ROWS_PER_THREAD
  // (2 RADIUS + 1). The loops unroll, and the taps' order is the two-pass
  // blur's (k = 0 .. 2 RADIUS).
  const int first = local.y * ROWS_PER_THREAD;
  REPRESENTATION_TYPE sums[ROWS_PER_THREAD];
  for (int r = 0; r < ROWS_PER_THREAD; ++r) sums[r] = REPRESENTATION_TYPE(0.0);
  for (int j = 0; j < ROWS_PER_THREAD + 2 * RADIUS; ++j) {
    const REPRESENTATION_TYPE v = rows[(first + j) * TILE_X + local.x];
    for (int r = 0; r < ROWS_PER_THREAD; ++r) {  // constant bounds: unrolled, sums in registers
      const int k = j - r;
      if (k >= 0 && k <= 2 * RADIUS) sums[r] += weights[k] * v;
    }
  }
  for (int r = 0; r < ROWS_PER_THREAD; ++r) {
    const ivec2 p = tile + ivec2(local.x, first + r);
    if (all(lessThan(p, size))) imageStore(target, ivec3(p, layer), representation_store(sums[r]));
  }
}
#elif PASS == 1
vec4 as_vec4(float m) { return vec4(m, 0.0, 0.0, 0.0); }
vec4 as_vec4(vec2 m) { return vec4(m, 0.0, 0.0); }
vec4 as_vec4(vec4 m) { return m; }

// Step 2 for FILTER_DIRECT_RUN consecutive texels of a row of layer
// u_first_layer: their taps, from the depth map, into the rows (as
// REPRESENTATION_TYPE floats). Each texel of the run's window is read and
// expanded once, not once for every tap that reads it.
void main() {
  const RepresentationConstants constants =
      RepresentationConstants(u_esm_c, u_evsm_positive, u_evsm_negative);
#if SAMPLES > 1
  const ivec2 size = textureSize(depth_map).xy;
#else
  const ivec2 size = textureSize(depth_map, 0).xy;
#endif
  const ivec2 p = ivec2(int(gl_GlobalInvocationID.x) * FILTER_DIRECT_RUN,
                        u_rows.x + int(gl_GlobalInvocationID.y));
  if (p.x >= size.x || p.y >= u_rows.y) return;
  const int layer = u_first_layer;
  REPRESENTATION_TYPE window[FILTER_DIRECT_RUN + 2 * RADIUS];
  for (int j = 0; j < FILTER_DIRECT_RUN + 2 * RADIUS; ++j) {
    const ivec3 q = ivec3(clamp(p.x + j - RADIUS, 0, size.x - 1), p.y, layer);
    window[j] = staged_expand(staged_texel(q, constants), constants);
  }
  for (int r = 0; r < FILTER_DIRECT_RUN; ++r) {
    // The taps' order is the tile's: the centre, then the pairs outwards.
    REPRESENTATION_TYPE sum = weights[RADIUS] * window[r + RADIUS];
    for (int k = 1; k <= RADIUS; ++k) {
      sum += weights[RADIUS + k] * (window[r + RADIUS - k] + window[r + RADIUS + k]);
    }
    // Past the map's right edge the store does nothing (an image's rules).
    imageStore(rows_image, ivec3(p.x + r, p.y - u_rows.z, 0), as_vec4(sum));
  }
}
#else
// Step 3 for FILTER_DIRECT_RUN consecutive texels of a column of layer
// u_first_layer: their column's taps of the rows, each row read once for
// the run, in the tile's order (k = 0 .. 2 RADIUS, from 0).
void main() {
  const ivec2 size = imageSize(target).xy;
  const ivec2 p = ivec2(gl_GlobalInvocationID.x,
                        u_rows.x + int(gl_GlobalInvocationID.y) * FILTER_DIRECT_RUN);
  if (p.x >= size.x || p.y >= u_rows.y) return;
  REPRESENTATION_TYPE sums[FILTER_DIRECT_RUN];
  for (int r = 0; r < FILTER_DIRECT_RUN; ++r) sums[r] = REPRESENTATION_TYPE(0.0);
  for (int j = 0; j < FILTER_DIRECT_RUN + 2 * RADIUS; ++j) {
    const int y = clamp(p.y + j - RADIUS, 0, size.y - 1) - u_rows.z;
    const REPRESENTATION_TYPE v = REPRESENTATION_TYPE(texelFetch(rows_map, ivec3(p.x, y, 0), 0));
    for (int r = 0; r < FILTER_DIRECT_RUN; ++r) {
      const int k = j - r;
      if (k >= 0 && k <= 2 * RADIUS) sums[r] += weights[k] * v;
    }
  }
  for (int r = 0; r < FILTER_DIRECT_RUN; ++r) {
    // The band's rows alone: the next band's are filtered from its own.
    if (p.y + r < u_rows.y) {
      imageStore(target, ivec3(p.x, p.y + r, u_first_layer), representation_store(sums[r]));
    }
  }
}
#endif
