// Soft shadows of a spot light's square source by backprojection
// (Guennebaud, Barthe and Paulin, "Real-time Soft Shadow Mapping by
// Backprojection", EGSR 2006), with the occluded part of the source kept
// as a bitmask of source samples (Schwarz and Stamminger, "Bitmask Soft
// Shadows", Eurographics 2007), so overlapping occluders are counted once.
//
// Each texel of the depth map in front of the receiver stands for a small
// square facing the light (a micro-occluder). Seen from the receiver it
// hides a rectangle of the source: by similar triangles, the ray from the
// receiver (map coordinate u_r, in units of tan, at depth d_r) to the
// source point l (world offset in the light's plane) crosses depth d at
// u = u_r + l (1/d - 1/d_r), so the texel [u0, u1] at depth d hides the
// source points with l in [u0 - u_r, u1 - u_r] / (1/d - 1/d_r), per axis.
// The source is a 16 x 16 grid of points, jittered per pixel by column and
// row so that each rectangle's points are a contiguous run of bits; the lit
// fraction is their radiometric average (cos theta_source cos
// theta_receiver / d^2, the traced reference's weights,
// src/reference/shadow_ray_tracer.cpp).
//
// What one map cannot show it misses: surfaces hidden from the source's
// centre but seen by the receiver through its edges (the slab's underside,
// an object behind another) do not block.
#pragma once
#include "accumulate.glsl"
#include "penumbra.glsl"

#define BACKPROJECTION_SIDE 16  // source points per side (a uint holds two rows)
// Micro-occluders per side of the search region at most; wider regions are
// read with a stride. Default scene, source 1.5, 1280x720, 2048^2 map:
// RMSE 0.0213 at 32, 0.0191 at 48, 0.0179 at 64 (llvmpipe: the lighting
// pass 4x PCSS's time).
#define BACKPROJECTION_MAX_STEPS 64
// Gathers per side of the coarse nearest-depth scan. With 8 the scan
// missed the thin pole for some receivers, whose search then spanned the
// whole near-plane cone at a stride that missed it too: lit streaks along
// its wide penumbra (default scene, 1.5: RMSE 0.0179; 0.0177 with 16).
#define BACKPROJECTION_SCAN 16

// Each micro-occluder is widened from half its stride to this many strides
// on each side, so that neighbouring texels at different depths, which
// project to rectangles of different scales, leave no gaps of light
// between them. Default scene, source 1.5, 480x270: RMSE 0.0216 at 0.5,
// 0.0200 at 0.7 and 0.8.
const float BACKPROJECTION_GROW = 0.7;

// Occluders below the receiver's tangent plane cannot block the light that
// reaches it (the rays that count lie above the plane), within this sine
// of slack for the facets of a mesh whose shading normals are smoothed.
const float BACKPROJECTION_PLANE_SLACK = 0.1;

// How many of the ascending coordinates lie below x.
uint backprojection_count_below(float x, float coords[BACKPROJECTION_SIDE]) {
  uint count = 0u;
  for (int i = 0; i < BACKPROJECTION_SIDE; ++i) count += coords[i] < x ? 1u : 0u;
  return count;
}

// Lit fraction of the receiver of lookup s (biased z-bar z, receiver-plane
// gradient `gradient` per texel, world normal `normal`) in perspective
// view `view` (layer `layer` of depth_maps), whose source is the square
// view.source_width wide in the view's x-y plane at its eye. `pixel`
// seeds the jitter of the source's grid of points.
float shadow_backprojection(sampler2DArray depth_maps, int layer, GpuShadowView view,
                            ShadowLookup s, float z, vec2 gradient, vec3 normal, ivec2 pixel) {
  ivec2 size = textureSize(depth_maps, 0).xy;
  float tan_per_texel = view.depth_range.z;
  float width = view.source_width;
  vec3 p = (view.view * vec4(s.position, 1.0)).xyz;  // the receiver in view space
  float d_r = -p.z;
  vec3 n = normalize(mat3(view.view) * normal);
  vec2 center = s.uv * vec2(size);  // texels
  vec2 u_r = (center - 0.5 * vec2(size)) * tan_per_texel;

  float xs[BACKPROJECTION_SIDE], ys[BACKPROJECTION_SIDE];
  for (int i = 0; i < BACKPROJECTION_SIDE; ++i) {
    vec3 h = accumulate_hash(pixel, 977 + i);
    xs[i] = ((float(i) + h.x) / float(BACKPROJECTION_SIDE) - 0.5) * width;
    ys[i] = ((float(i) + h.y) / float(BACKPROJECTION_SIDE) - 0.5) * width;
  }

  // Blockers lie in the cone from the receiver to the source, widest at
  // the view's near plane; a coarse scan finds the nearest depth in front
  // of the receiver there, and the cone through that depth is the region
  // searched.
  float near_reach =
      0.5 * width * max(1.0 / view.depth_range.x - 1.0 / d_r, 0.0) / tan_per_texel + 0.5;
  float nearest = z;
  for (int iy = 0; iy < BACKPROJECTION_SCAN; ++iy) {
    for (int ix = 0; ix < BACKPROJECTION_SCAN; ++ix) {
      vec2 c = center + (2.0 * (vec2(ix, iy) + 0.5) / float(BACKPROJECTION_SCAN) - 1.0) *
                            near_reach;
      vec4 d = textureGather(depth_maps, vec3(c / vec2(size), float(layer)), 0);
      nearest = min(nearest, min(min(d.x, d.y), min(d.z, d.w)));
    }
  }
  float reach = near_reach;
  if (nearest < z) {
    float d_min = linear_depth_of(view, nearest);
    reach = min(0.5 * width * max(1.0 / d_min - 1.0 / d_r, 0.0) / tan_per_texel + 1.0, reach);
  }
  int steps = clamp(int(ceil(2.0 * reach)), 1, BACKPROJECTION_MAX_STEPS);
  float stride = 2.0 * reach / float(steps);  // texels per micro-occluder
  float half_extent = BACKPROJECTION_GROW * stride * tan_per_texel;

  uint blocked[BACKPROJECTION_SIDE / 2];  // row j: bits 16 (j & 1) + i of blocked[j / 2]
  for (int j = 0; j < BACKPROJECTION_SIDE / 2; ++j) blocked[j] = 0u;
  for (int iy = 0; iy < steps; ++iy) {
    for (int ix = 0; ix < steps; ++ix) {
      vec2 c = center - vec2(reach) + (vec2(ix, iy) + 0.5) * stride;
      ivec2 texel = ivec2(floor(c));
      if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) continue;
      float occluder = texelFetch(depth_maps, ivec3(texel, layer), 0).r;
      if (occluder >= z + dot(gradient, c - center)) continue;  // behind the receiver's plane
      float d = linear_depth_of(view, occluder);
      vec2 u = (c - 0.5 * vec2(size)) * tan_per_texel;
      vec3 to_occluder = vec3(u * d, -d) - p;
      if (dot(to_occluder, n) <= -BACKPROJECTION_PLANE_SLACK * length(to_occluder)) continue;
      float k = 1.0 / d - 1.0 / d_r;
      if (k <= 0.0) continue;
      vec2 lo = (u - half_extent - u_r) / k, hi = (u + half_extent - u_r) / k;
      uint first_column = backprojection_count_below(lo.x, xs);
      uint end_column = backprojection_count_below(hi.x, xs);
      if (first_column == end_column) continue;
      uint first_row = backprojection_count_below(lo.y, ys);
      uint end_row = backprojection_count_below(hi.y, ys);
      uint columns = ((1u << end_column) - 1u) & ~((1u << first_column) - 1u);
      for (uint r = first_row; r < end_row; ++r) blocked[r >> 1u] |= columns << (16u * (r & 1u));
    }
  }

  // The source faces the view's -z, so cos theta_source d = d_r for every
  // point; it cancels in the ratio.
  float total = 0.0, lit = 0.0;
  for (int j = 0; j < BACKPROJECTION_SIDE; ++j) {
    uint row = blocked[j >> 1] >> uint(16 * (j & 1));
    for (int i = 0; i < BACKPROJECTION_SIDE; ++i) {
      vec3 t = vec3(xs[i], ys[j], 0.0) - p;
      float d2 = dot(t, t);
      float weight = max(dot(n, t), 0.0) / (d2 * d2);
      total += weight;
      if (((row >> uint(i)) & 1u) == 0u) lit += weight;
    }
  }
  return total > 0.0 ? lit / total : 1.0;
}
