// Dithered hard shadows for --accumulate N (src/render/accumulation.hpp).
// Sub-frame k renders a spot light's map from a point of its own cell of
// the square: the N cells, of equal area, partition the square for any N
// (square_cell in src/core/light_sampling.hpp: m = floor(sqrt(N)) columns
// of floor(N/m) or ceil(N/m) cells each), so every cell is some sub-frame's
// exactly once. Averaged, the N hard shadows would show N stepped copies
// of each wide penumbra's edge. So each pixel tests rays to points of its
// own inside the sub-frame's cell (ACCUMULATE_RAYS of them, one in each of
// k x k sub-cells), jittered anew every sub-frame: the average is fine
// noise, not steps, and over the N sub-frames each pixel's points cover
// the whole square once, so the estimate is unbiased for every N. The
// host hands the shader the cell (GpuShadow's accumulate_cell_*), so the
// two cannot disagree on it.
//
// The pixel's points are multi-jittered as well (Chiu, Shirley and Wang,
// "Multi-Jittered Sampling", Graphics Gems IV, 1994): in the cell at row r
// of its column's c cells, the x coordinate falls in one of the cell's
// k^2 c fine strata, chosen through a permutation of the rows seeded by
// the pixel and fixed across sub-frames, so over the column's c cells the
// pixel's x coordinates fill every fine stratum of the column once (and so
// of the square); in y each of the m columns takes its own of the cells'
// m sub-rows (where the columns hold equally many cells, the pixel's y
// coordinates fill every fine stratum of a row once). An occluder edge
// parallel to the square's sides (a box's edge under a spot light facing
// it) is then integrated with error O(1/N) rather than the O(N^-3/4) of
// jittered cells alone. Measured on the default scene (spot light, source
// 1.5 wide, N = 64, against a 2048-ray reference): RMSE 0.0074 with one
// jittered point per cell, 0.0062 with these; 9 rays per cell instead of
// 4 measured the same, so the rest is the N maps' own (N = 256: 0.0030).
//
// The map was rendered from the sub-frame's point; the ray from the
// receiver to the point moved by delta (in the map's x and y) crosses
// linear depth z at the receiver's map position shifted by
// delta (1/z - 1/z_r) / (texel size at unit depth) texels (similar
// triangles). The ray is walked through every texel it crosses, from the
// receiver's to the view's near plane (Amanatides and Woo, "A Fast Voxel
// Traversal Algorithm for Ray Tracing", Eurographics 1987), and is blocked
// in the first texel where it crosses the depth of the surface the map
// holds there, in front of the receiver's own plane (as PCF compares with
// the receiver plane, so a sloped receiver does not shadow itself). A
// march that sampled the ray at steps longer than a texel would skip thin
// occluders (a pole one texel wide) and leak light through them.
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
// the host chose (its corner and size in [0, 1]^2, its column of
// `columns`, its row of the `rows` its column holds) and the pixel's first
// fine stratum in x and y there, through the permutations its seed picks.
// The same for all of the pixel's rays in the sub-frame.
struct AccumulateCell {
  vec2 point;   // the sub-frame's point, in the cell
  vec2 origin;  // the cell's lower corner
  vec2 size;    // the cell's width and height
  uint columns, rows;
  uint first_x, first_y;
};

AccumulateCell accumulate_cell(ivec2 pixel, vec2 point, vec4 cell_rect, ivec4 index) {
  AccumulateCell cell;
  cell.point = point;
  cell.origin = cell_rect.xy;
  cell.size = cell_rect.zw;
  uint column = uint(index.x), row = uint(index.z);
  cell.columns = uint(max(index.y, 1));
  cell.rows = uint(max(index.w, 1));
  const uint rays = uint(ACCUMULATE_RAYS);
  uvec3 seed = accumulate_pcg3d(uvec3(uvec2(pixel), 0x9e3779b9u));
  cell.first_x = rays * accumulate_permute(row, cell.rows, seed.x);
  cell.first_y = rays * accumulate_permute(column, cell.columns, seed.y);
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
  vec2 fraction = (vec2(fine_x, fine_y) + jitter) / vec2(rays * cell.rows, rays * cell.columns);
  vec2 moved = cell.origin + fraction * cell.size;
  return (moved - cell.point) * view.source_width;
}

// Fraction of light (0 or 1) along the ray to the light moved by
// `light_offset` (world units, perspective views only). `z` is the
// receiver's biased z-bar, `gradient` its plane's z-bar change per texel.
float shadow_hard_dithered(sampler2DArray depth_maps, int layer, GpuShadowView view,
                           ShadowLookup s, float z, vec2 gradient, vec2 light_offset) {
  ivec2 size = textureSize(depth_maps, 0).xy;
  vec2 start = s.uv * vec2(size);
  // No early test of the receiver's own texel: the map says whether the
  // sub-frame's point sees the receiver, not whether the moved point does
  // (ending there would darken every penumbra: the dither could take light
  // away but never give it).
  float bias = s.depth - z;
  float inverse_receiver = 1.0 / linear_depth_of(view, s.depth);
  float t_max = max(1.0 / view.depth_range.x - inverse_receiver, 0.0);
  vec2 reach = light_offset * t_max / view.depth_range.z;  // texels, at the near plane
  // The walk: f in [0, 1] runs from the receiver to the near plane; in
  // each axis the next texel boundary is crossed at f = next and then
  // every `delta` (Amanatides and Woo).
  ivec2 texel = ivec2(floor(start));
  vec2 magnitude = abs(reach);
  // An axis the ray moves less than a millionth of a texel along is never
  // crossed (f = 2), which also keeps 1 / magnitude finite.
  bvec2 moving = greaterThan(magnitude, vec2(1e-6));
  ivec2 advance = ivec2(sign(reach)) * ivec2(moving);
  vec2 delta = 1.0 / max(magnitude, vec2(1e-6));
  vec2 inside = start - vec2(texel);  // [0, 1): where the start lies in its texel
  vec2 next = vec2(advance.x > 0 ? 1.0 - inside.x : inside.x,
                   advance.y > 0 ? 1.0 - inside.y : inside.y);
  next = mix(vec2(2.0), next * delta, moving);
  float ray_in = s.depth;  // the ray's z-bar where it enters the texel
  // A segment inside the map crosses at most size.x + size.y texels; one
  // that crosses more has left the map, past which nothing is known.
  for (int j = 0; j <= size.x + size.y; ++j) {
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) break;
    float f_out = min(min(next.x, next.y), 1.0);
    float ray_out = relative_depth_of(view, 1.0 / (t_max * f_out + inverse_receiver));
    float receiver = z + dot(gradient, vec2(texel) + 0.5 - start);
    float occluder = texelFetch(depth_maps, ivec3(texel, layer), 0).r;
    // Blocked where the ray crosses the occluder's depth within this
    // texel; in the last texel, anything up to the near plane.
    bool last = f_out >= 1.0;
    bool crossed = last || occluder >= ray_out - bias;
    if (occluder < min(ray_in - bias, receiver) && crossed) return 0.0;
    if (last) break;
    ray_in = ray_out;
    if (next.x < next.y) {
      texel.x += advance.x;
      next.x += delta.x;
    } else {
      texel.y += advance.y;
      next.y += delta.y;
    }
  }
  return 1.0;
}
