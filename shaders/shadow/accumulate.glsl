// Dithered hard shadows for --accumulate N (src/render/accumulation.hpp).
// Sub-frame k renders a spot light's map from point k of a correlated
// multi-jittered pattern over its square (Kensler 2013): one point in
// each cell of an m x rows grid (m = floor(sqrt(N))). Averaged, the N hard
// shadows would show N stepped copies of each wide penumbra's edge. So
// each pixel tests rays to points of its own inside the sub-frame's cell
// (ACCUMULATE_RAYS of them, one in each of k x k sub-cells), jittered anew
// every sub-frame: the average is fine noise, not steps, and every pixel
// samples each sub-cell of the square exactly once over the N sub-frames,
// so the estimate stays unbiased.
//
// The pixel's points are multi-jittered as well (Chiu, Shirley and Wang,
// "Multi-Jittered Sampling", Graphics Gems IV, 1994): in cell (c, r) the
// x coordinate falls in one of the cell's k^2 rows-wide fine strata chosen
// through a permutation seeded by the pixel and fixed across sub-frames,
// and likewise for y. Over the N sub-frames each pixel's x coordinates
// then fill all of the square's fine strata once, so an occluder edge
// parallel to the square's sides (a box's edge under a spot light facing
// it) is integrated with error O(1/N) rather than the O(N^-3/4) of
// jittered cells alone. Measured on the default scene (spot light, source
// 1.5 wide, N = 64, against a 2048-ray reference): RMSE 0.0074 with one
// jittered point per cell, 0.0062 with these; 9 rays per cell instead of
// 4 measured the same, so the rest is the N maps' own (N = 256: 0.0030).
//
// The map was rendered from the sub-frame's point; the ray from the
// receiver to the point moved by delta (in the map's x and y) crosses
// linear depth z at the receiver's map position shifted by
// delta (1/z - 1/z_r) / (texel size at unit depth) texels (similar
// triangles). The ray is marched through the map from the receiver to the
// view's near plane, and is blocked where it crosses the depth of a
// surface the map holds there, in front of the receiver's own plane (as
// PCF compares with the receiver plane, so a sloped receiver does not
// shadow itself).
#pragma once


#define ACCUMULATE_RAYS_PER_SIDE 2
#define ACCUMULATE_RAYS (ACCUMULATE_RAYS_PER_SIDE * ACCUMULATE_RAYS_PER_SIDE)

// A hash (pcg3d; Jarzynski & Olano, "Hash Functions for GPU Rendering",
// JCGT 2020) of the pixel and a seed as three values in [0, 1).
uvec3 accumulate_pcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

vec3 accumulate_hash(ivec2 pixel, int frame) {
  return vec3(accumulate_pcg3d(uvec3(uvec2(pixel), uint(frame))) >> 8u) * (1.0 / 16777216.0);
}

// A permutation of [0, l) chosen by p (Kensler 2013, "Correlated
// Multi-Jittered Sampling", Listing 3), the one the CPU's cmj_sample uses.
uint accumulate_permute(uint i, uint l, uint p) {
  uint w = l - 1u;
  w |= w >> 1u;
  w |= w >> 2u;
  w |= w >> 4u;
  w |= w >> 8u;
  w |= w >> 16u;
  do {
    i ^= p;
    i *= 0xe170893du;
    i ^= p >> 16u;
    i ^= (i & w) >> 4u;
    i ^= p >> 8u;
    i *= 0x0929eb3fu;
    i ^= p >> 23u;
    i ^= (i & w) >> 1u;
    i *= 1u | p >> 27u;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11u;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2u;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2u;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5u;
  } while (i >= l);
  return (i + p) % l;
}

// The sub-frame's cell of the square as one pixel samples it: the cell
// (c, r) of cmj_sample's grid (Kensler 2013, Listing 6: m columns, rows
// rows) holding the sub-frame's `point`, and the pixel's first fine
// stratum in x and y there, through the permutations its seed picks.
// The same for all of the pixel's rays in the sub-frame.
struct AccumulateCell {
  vec2 point;  // the sub-frame's point, in [0, 1]^2 of the square
  uint m, rows, c, r;
  uint first_x, first_y;
};

AccumulateCell accumulate_cell(ivec2 pixel, int count, vec2 point) {
  AccumulateCell cell;
  cell.point = point;
  uint n = uint(count);
  cell.m = uint(sqrt(float(n)));
  while (cell.m * cell.m > n) --cell.m;
  while ((cell.m + 1u) * (cell.m + 1u) <= n) ++cell.m;
  cell.rows = (n + cell.m - 1u) / cell.m;
  cell.c = min(uint(point.x * float(cell.m)), cell.m - 1u);
  cell.r = min(uint(point.y * float(cell.rows)), cell.rows - 1u);
  const uint rays = uint(ACCUMULATE_RAYS);
  uvec3 seed = accumulate_pcg3d(uvec3(uvec2(pixel), 0x9e3779b9u));
  cell.first_x = rays * accumulate_permute(cell.r, cell.rows, seed.x);
  cell.first_y = rays * accumulate_permute(cell.c, cell.m, seed.y);
  return cell;
}

// The pixel's ray q (0 <= q < ACCUMULATE_RAYS) of this sub-frame: its
// light offset in world units along the map's x and y, from the
// sub-frame's point to the pixel's point in the same cell. `jitter` in
// [0, 1)^2 places the point within its fine strata.
vec2 accumulate_light_offset(GpuShadowView view, AccumulateCell cell, int q, vec2 jitter) {
  // Ray q takes sub-cell (qx, qy) of the cell's k x k, and within it the
  // fine strata of the canonical multi-jittered arrangement (Chiu et al.,
  // Figure 3): k qx + qy of the cell's k^2 in x, k qy + qx in y.
  const uint k = uint(ACCUMULATE_RAYS_PER_SIDE), rays = k * k;
  uint qx = uint(q) % k, qy = uint(q) / k;
  uint fine_x = cell.first_x + k * qx + qy;
  uint fine_y = cell.first_y + k * qy + qx;
  vec2 moved = vec2(
      (float(cell.c) + (float(fine_x) + jitter.x) / float(rays * cell.rows)) / float(cell.m),
      (float(cell.r) + (float(fine_y) + jitter.y) / float(rays * cell.m)) / float(cell.rows));
  return (moved - cell.point) * view.source_width;
}

// Fraction of light (0 or 1) along the ray to the light moved by
// `light_offset` (world units, perspective views only). `z` is the
// receiver's biased z-bar, `gradient` its plane's z-bar change per texel,
// `jitter` in [0, 1) places the march's steps.
float shadow_hard_dithered(sampler2DArray depth_maps, int layer, GpuShadowView view,
                           ShadowLookup s, float z, vec2 gradient, vec2 light_offset,
                           float jitter) {
  ivec2 size = textureSize(depth_maps, 0).xy;
  vec2 center = s.uv * vec2(size);
  // No early test of the receiver's own texel: the map says whether the
  // sub-frame's point sees the receiver, not whether the moved point does
  // (ending there would darken every penumbra: the dither could take light
  // away but never give it).
  float bias = s.depth - z;
  float z_receiver = linear_depth_of(view, s.depth);
  float t_max = max(1.0 / view.depth_range.x - 1.0 / z_receiver, 0.0);
  vec2 reach = light_offset * t_max / view.depth_range.z;  // texels, at the near plane
  int steps = clamp(int(ceil(0.5 * length(reach))), 1, 16);  // about one per 2 texels
  // Each step covers the ray from the previous point towards the light: it
  // is blocked where, at the step's texel, the map's surface lies in that
  // stretch of depth (the ray crosses it), in front of the receiver's
  // plane. The last step takes everything up to the near plane.
  float previous = s.depth;
  for (int j = 0; j < steps; ++j) {
    float f = (float(j) + jitter) / float(steps);  // (0, 1): receiver to near plane
    vec2 offset = reach * f;
    ivec2 texel = ivec2(floor(center + offset));
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) break;
    float ray = relative_depth_of(view, 1.0 / (t_max * f + 1.0 / z_receiver));
    float receiver = z + dot(gradient, offset);
    float occluder = texelFetch(depth_maps, ivec3(texel, layer), 0).r;
    bool crossed = j == steps - 1 || occluder >= ray - bias;
    if (occluder < min(previous - bias, receiver) && crossed) return 0.0;
    previous = ray;
  }
  return 1.0;
}
