// Soft shadows of a light's source by backprojection
// (Guennebaud, Barthe and Paulin, "Real-time Soft Shadow Mapping by
// Backprojection", EGSR 2006), with the occluded part of the source kept
// as a bitmask of source samples (Schwarz and Stamminger, "Bitmask Soft
// Shadows", Eurographics 2007), so overlapping occluders are counted once.
//
// Each texel of the depth map in front of the receiver is a small square
// facing the light (a micro-patch) exactly where the texel lies, so a
// silhouette stays on its texel boundary whatever the receiver's position
// inside its own texel. Seen from the receiver it hides a rectangle of the
// source: by similar triangles, the ray from the receiver (map coordinate
// u_r, in units of tan, at depth d_r) to the source point l (world offset
// in the light's plane) crosses depth d at u = u_r + l (1/d - 1/d_r), so
// the texel [u0, u1] at depth d hides the source points with l in
// [u0 - u_r, u1 - u_r] / (1/d - 1/d_r), per axis. Neighbouring patches at
// different depths project to rectangles of different scales: each patch
// reaches to its blocking neighbours' projection of their shared edge
// (Guennebaud et al. 2006, section 4.2's gap filling), so no light leaks
// between them.
//
// The blockers' region comes from the map's min/max depth hierarchy
// (Guennebaud, Barthe and Paulin, "High-Quality Adaptive Soft Shadow
// Mapping", Eurographics 2007; Schwarz and Stamminger 2007;
// shaders/filter/depth_hierarchy.comp): the cone from the receiver to the
// source, cut at the nearest depth the hierarchy finds in it, holds every
// texel that can hide part of the source. All of it behind the receiver
// is light, all of it in front is umbra; otherwise its texels (or, for a
// region over the settings' backprojection_cells texels wide, the
// hierarchy's cells) are the patches, so the work per pixel is bounded.
//
// The source is 16 x 16 points, one in each cell of a 16 x 16 grid and
// multi-jittered (Chiu, Shirley and Wang, "Multi-Jittered Sampling",
// Graphics Gems IV, 1994): no two share a column or a row of the 256 x
// 256 finer grid, so an edge along either axis hides one of 257 fractions
// of the source, not one of 17 (a regular grid shifted per pixel read a
// straight edge's penumbra with a pixel-to-pixel noise of RMS 0.021). In
// each row of cells the points hidden by a rectangle are still a run of
// columns, whose ends take one of two values each, found in closed form;
// so in each column. The hidden points are 256 bits in two uvec4
// registers. The lit fraction is their radiometric average (cos
// theta_source cos theta_receiver / d^2, the traced reference's weights,
// src/reference/shadow_ray_tracer.cpp).
//
// Every light type: a spot light's square source (perspective view), a
// point light's sphere seen from a cube face (the disc through its centre
// facing the face's axis; the map stores distances from the light, made
// axial per texel) and the sun's disc of directions (orthographic
// cascades: a texel at depth d hides the directions l, in tangent units,
// with l in [x0 - x_r, x1 - x_r] / (d_r - d)). Blockers beyond a cube
// face's edge are in its guard band, and past it in the other faces.
//
// What one map cannot show it misses: surfaces hidden from the source's
// centre but seen by the receiver through its edges (the slab's underside,
// an object behind another) do not block.
#pragma once
#include "accumulate.glsl"
#include "depth_map_hooks.glsl"
#include "fetch_count.glsl"
#include "penumbra.glsl"
#include "view_select.glsl"

#define BACKPROJECTION_SIDE 16  // source points per side (a uint holds two rows)
// The settings' backprojection_cells (include/penumbra/settings.hpp, with
// what it costs and buys): patches per side of the blockers' region at
// most; a wider region is read from the hierarchy's level whose cells it
// spans in at most this many.
// The coarsest cells (2^level texels wide) whose 2 x 2 around the receiver
// are read as texels: up to 16 x 16 gathers; coarser ones around them as
// cells (backprojection_near_patches()). Default scene, source 1.5,
// 4096^2 maps (cells of 8 texels), 640x360: RMSE 0.0148 at 2, 0.0117 at 3.
#define BACKPROJECTION_REFINE_LEVEL 3
// How far apart, in source widths, the projections of a 2 x 2 of cells'
// nearest and farthest depths may lie for it to be read as one patch.
const float BACKPROJECTION_FLAT = 1.0 / 64.0;
// The steepest slope, in depth per cell width, of a surface joining two
// neighbouring cells (86 degrees from facing the light); a larger
// difference in their depths is a step (backprojection_joined()).
// Spot 1.5, 640x360, RMSE at 4, 8, 16 and 64: the default scene 0.0049,
// 0.0047, 0.0047, 0.0047; the foliage 0.0211, 0.0207, 0.0202, 0.0201.
const float BACKPROJECTION_STEP = 16.0;
// The narrowest cell, in texels, that a step is measured in: between
// texels, or cells 2 texels wide, a step is one of over 4 x 16 texel
// widths of depth. Between texels, at backprojection_cells 64 (640x360,
// RMSE), 1 -> this: the default scene's sun at 8.45 degrees 0.0037 ->
// 0.0035, the foliage's sun at 8.90 degrees 0.0199 -> 0.0193 (its
// leaves' walls stand for the layers the map lost; with every texel's
// wall, as before, 0.0051 and 0.0194); 8: 0.0035 and 0.0194.
const int BACKPROJECTION_STEP_CELL = 4;

// Occluders below the receiver's tangent plane cannot block the light that
// reaches it (the rays that count lie above the plane), within a sine of
// slack for the facets of a mesh whose shading normals are smoothed: at
// least this, and twice the sine of the angle between the receiver's
// triangle's normal and its shading normal. The rays that count lie above
// the shading normal's horizon (docs/comparing.md, "The terminator
// model"), which dips below the triangle's plane by that angle; a vertex
// normal is the mean of its faces', so the facet beyond an edge is tilted
// from the triangle by about twice it. RMSE at 640x360 with 0.1 alone ->
// this: bunny, spot 0.5 0.0111 -> 0.0103, spot 1.5 0.0097 -> 0.0092,
// point 1.5 0.0105 -> 0.0100, sun 11.86 degrees 0.0250 -> 0.0196; the
// default scene's sun at 8.45 degrees 0.0039 -> 0.0036, its other cells
// and the foliage's within 0.0001. Once the angle's sine: the bunny's
// spot 0.5 0.0107, its sun 0.0203; 0.2 for every receiver made the
// foliage's spot at 1.5 0.0170 -> 0.0173.
const float BACKPROJECTION_PLANE_SLACK = 0.1;

// How sharply the points nearest below the horizon stand for a sliver of
// the source above it that no point reaches (backprojection_lit_fraction()):
// a point 1/256 further below weighs 1/e as much. At 64 and 256 the
// default scene's sun at 8.45 degrees read 0.00285 (1280x720), every other
// cell of the study within 0.0001 or better.
const float BACKPROJECTION_SLIVER_SHARPNESS = 256.0;

// Backprojection's normal offset, in texels, for a receiver whose
// triangle's normal makes the angle theta with the direction to the light
// `to_light`, where the settings' max_slope caps its depth gradient
// (receiver_depth_gradient()): none where cos theta is at least the cap's
// cosine 1 / sqrt(1 + max_slope^2), rising to the settings' normal_offset
// at grazing and beyond. The offset moves the lookup normal_offset sin
// theta texels across the map, and every shadow on the receiver with it,
// where the traced reference starts its rays on the surface: on a
// surface lit at grazing that is normal_offset tan theta texels along
// it, and a blocker a few texels in front (the foliage's fence rails,
// 78 degrees from facing its lamp) threw its shadow two pixels off. Where
// the gradient follows the surface, the receiver's plane (and
// backprojection_above_plane()) keeps its own texels out without it;
// past the cap the plane no longer follows them, and past grazing the
// plane is cut flat at the receiver's depth (backprojection_receiver())
// and its slack lets the edge of a convex face's neighbour in (the
// default scene's box side, 3 degrees past grazing under the 8.45 degree
// sun, streaked from its top edge: 0.0285 without any offset). RMSE at
// 640x360, 2048^2 maps, 256 rays, the offset times 1 - cos theta (as
// before) -> this: foliage, point 0.5 0.0330 -> 0.0208, point 1.5 0.0235
// -> 0.0213, sun 2.97 degrees 0.0348 -> 0.0270, sun 8.90 degrees 0.0225
// -> 0.0194, spot 1.5 0.0170 -> 0.0157; bunny, spot 0.5 0.0103 ->
// 0.0098, spot 1.5 0.0092 -> 0.0089, point 1.5 0.0100 -> 0.0093, sun
// 11.86 degrees 0.0196 -> 0.0189; the default scene within 0.0001 but
// its sun at 2.82 degrees, 0.0035 -> 0.0039 (a few pixels at the tip of
// the torus's self-shadow, along its terminator). Cut at a cosine of 0.3
// instead: that one 0.0035, the foliage's point 0.5 0.0228 and sun 2.97
// degrees 0.0281; at 0.05, 0.0043, 0.0205 and 0.0269.
float backprojection_normal_offset(float normal_offset, float max_slope, vec3 normal,
                                   vec3 to_light) {
  float capped_cos = inversesqrt(1.0 + max_slope * max_slope);
  return normal_offset * clamp(1.0 - dot(normal, to_light) / capped_cos, 0.0, 1.0);
}

// BACKPROJECTION_BIAS_MAX_SLOPE (shared/bindings.h): the steepest slope
// tan(theta) backprojection's slope-scaled bias follows (the settings'
// max_slope, 10 by default, still caps the receiver's depth gradient).
// The hard test compares the receiver with a texel's depth up
// to half a texel away, an error of up to half a texel times tan(theta)
// that the slope-scaled bias covers; backprojection compares each patch
// with the receiver's plane at the patch's own centre, and a bias of up to
// 15 texels of depth (1.5 x 10) at a steep receiver dropped the blockers
// near it: the foliage's leaves under the sun, the bunny's flanks. RMSE at
// 640x360, the cap at 10 -> 2: bunny, spot 0.5 0.0115 -> 0.0111, spot 1.5
// 0.0100 -> 0.0097, point 1.5 0.0117 -> 0.0105, sun 11.86 degrees 0.0273
// -> 0.0249; foliage, sun 8.90 degrees 0.0299 -> 0.0225, spot 1.5 0.0169
// -> 0.0170; the default scene's five cells unchanged; `scenes/creases.json`
// (480x270, source 1.0) 0.0220 unchanged, `far_ground` 0.0438 -> 0.0396.
// At 1: the foliage's sun 0.0213, but creases 0.0231; at 3: 0.0237 and
// 0.0216.

// The settings `params` as backprojection's lookup and bias take them for a
// receiver with the triangle's normal `normal`: its share of the normal
// offset (backprojection_normal_offset()) and a slope-scaled bias that
// follows the slope up to BACKPROJECTION_BIAS_MAX_SLOPE.
GpuShadow backprojection_bias_settings(GpuShadow params, vec3 normal, vec3 to_light) {
  params.normal_offset =
      backprojection_normal_offset(params.normal_offset, params.max_slope, normal, to_light);
  params.max_slope = min(params.max_slope, BACKPROJECTION_BIAS_MAX_SLOPE);
  return params;
}

// The depth along the view's -z of z-bar `z_bar` stored at map offset
// `u` (tangent units from the map's centre): a cube face stores distances
// from the light (radial_depth), the axial depth d / sqrt(1 + |u|^2).
float backprojection_depth(GpuShadowView view, float z_bar, vec2 u) {
  float d = linear_depth_of(view, z_bar);
  return view.radial_depth != 0 ? d * inversesqrt(1.0 + dot(u, u)) : d;
}

// How far a blocker at axial depth d is from the receiver at inverse
// depth r_inverse (1 / d_r, perspective) or depth d_r (orthographic), in
// the units that make a map offset over it an offset on the source: 1/d -
// 1/d_r (perspective: tangent / world) or d_r - d (orthographic: world /
// tangent).
float backprojection_k(GpuShadowView view, float d, float receiver) {
  return view.perspective != 0 ? 1.0 / d - receiver : receiver - d;
}

// The texels [first, last] whose squares meet the open square of half-width
// `reach` texels around `center`, inside the map.
void backprojection_region(vec2 center, float reach, ivec2 size, out ivec2 first, out ivec2 last) {
  first = max(ivec2(floor(center - reach)), ivec2(0));
  last = max(min(ivec2(ceil(center + reach)) - 1, size - 1), first);
}

// The texels [first, last] of a cube face's region of half-width `reach`
// texels around `center`, past the face's map (`size` texels) into the
// other faces up to a map's width (backprojection_cube_cell()).
void backprojection_outer_region(vec2 center, float reach, ivec2 size, out ivec2 first,
                                 out ivec2 last) {
  first = max(ivec2(floor(center - reach)), -size);
  last = min(ivec2(ceil(center + reach)) - 1, 2 * size - 1);
}

// The hierarchy's levels and the size of level l: OpenGL's chain, floor(
// size / 2^l) (taken from level 0: textureSize() at a level chosen at run
// time read level 2's size on llvmpipe).
int backprojection_levels(sampler2DArray hierarchy) {
  ivec2 size = textureSize(hierarchy, 0).xy;
  return findMSB(max(size.x, size.y)) + 1;
}
ivec2 backprojection_cells(sampler2DArray hierarchy, int level) {
  return max(textureSize(hierarchy, 0).xy >> level, ivec2(1));
}

// The nearest and farthest depth over texels [first, last] (a superset: the
// hierarchy's cells covering them). Level l's cells are 2^(l + 1) texels
// wide (the last one takes an odd remainder), so the level where a cell is
// at least half the span covers it in at most 3 x 3 cells.
vec2 backprojection_depth_bounds(sampler2DArray hierarchy, int layer, ivec2 first, ivec2 last) {
  int span = max(last.x - first.x, last.y - first.y) + 1;
  int level = clamp(findMSB(max(span - 1, 0)) - 1, 0, backprojection_levels(hierarchy) - 1);
  ivec2 cells = backprojection_cells(hierarchy, level);
  ivec2 lo = min(first >> (level + 1), cells - 1), hi = min(last >> (level + 1), cells - 1);
  vec2 bounds = vec2(1.0e30, -1.0e30);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 3; ++x) {
      ivec2 c = lo + ivec2(x, y);
      if (any(greaterThan(c, hi))) continue;
      vec2 m = texelFetch(hierarchy, ivec3(c, layer), level).rg;
      SHADOW_FETCHED(1);
      bounds = vec2(min(bounds.x, m.x), max(bounds.y, m.y));
    }
  }
  return bounds;
}

// The source's points: point (i, j) of the 16 x 16 lies at
// ((i + o(j, shift.x)) / 16 - 1/2, (j + o(i, shift.y)) / 16 - 1/2) widths
// of the window (BackprojectionReceiver::window) from its centre, its
// offset in the cell o(k, shift) = fract(shift + reverse(k) / 16)
// (reverse: of k's 4 bits), the shift drawn per pixel. Unshifted, they
// are the 256 points of Hammersley's set, a (0, 8, 2)-net in base 2; the
// shift moves each point inside its cell, keeping one point in each of
// the 256 columns and the 256 rows of the finer grid.
float backprojection_offset(int k, float shift) {
  return fract(shift + float(bitfieldReverse(uint(k)) >> 28u) * (1.0 / 16.0));
}

// The rows k (bit k) whose offset o(k, shift) lies below t, 0 < t <= 1:
// with q = 16 shift, 16 o(k) = (reverse(k) + floor(q)) mod 16 + fract(q),
// below 16 t where (reverse(k) + floor(q)) mod 16 < n = ceil(16 t -
// fract(q)): the bits of the n values of reverse(k) from 16 - floor(q)
// (cyclically), their indices reversed (two delta swaps: index bits 0 and
// 3, then 1 and 2).
uint backprojection_offsets_below(float t, float shift) {
  float q = 16.0 * shift;
  float whole = floor(q);
  uint n = uint(clamp(ceil(16.0 * t - (q - whole)), 0.0, 16.0));
  uint start = uint(16.0 - whole) & 15u;
  uint run = (1u << n) - 1u;
  uint values = ((run << start) | (run >> (16u - start))) & 0xffffu;
  uint swap = ((values >> 7u) ^ values) & 0x00aau;
  values ^= swap | (swap << 7u);
  swap = ((values >> 2u) ^ values) & 0x0c0cu;
  return values ^ (swap | (swap << 2u));
}

// How many points of each row lie below grid coordinate u (points i with
// i + o < u, u = (x / width + 1/2) 16): `count` in the rows `rows` (bit
// j), count - 1 in the others; a count of 0 holds in every row. (Of each
// column, for y, likewise.)
struct BackprojectionEdge {
  uint count;
  uint rows;
};
BackprojectionEdge backprojection_edge(float u, float shift) {
  u = clamp(u, 0.0, float(BACKPROJECTION_SIDE));
  float whole = ceil(u);
  // i + o < u: i < ceil(u) where o < u - ceil(u) + 1, else i < ceil(u) - 1.
  return BackprojectionEdge(uint(whole), backprojection_offsets_below(u - whole + 1.0, shift));
}

// Bits [0, n) of a row, n = 0..16.
uint backprojection_below(uint n) {
  return (1u << n) - 1u;
}

// Marks hidden the points inside [lo, hi] (the window's widths from its
// centre, per axis). In row j the points [c0(j), c1(j)) lie inside along
// x, each end one of two runs (backprojection_edge()); in column i the
// points [r0(i), r1(i)) along y. A point is hidden where both hold. Row j
// is bits 16 (j & 1) + i of word j / 2 of (low, high); every index is a
// constant, so the mask stays in registers.
void backprojection_hide(inout uvec4 low, inout uvec4 high, vec2 lo, vec2 hi, vec2 shift) {
  vec2 u0 = (lo + 0.5) * float(BACKPROJECTION_SIDE), u1 = (hi + 0.5) * float(BACKPROJECTION_SIDE);
  if (any(lessThanEqual(u1, vec2(0.0))) || any(greaterThanEqual(u0, vec2(BACKPROJECTION_SIDE)))) {
    return;
  }
  BackprojectionEdge x0 = backprojection_edge(u0.x, shift.x);
  BackprojectionEdge x1 = backprojection_edge(u1.x, shift.x);
  BackprojectionEdge y0 = backprojection_edge(u0.y, shift.y);
  BackprojectionEdge y1 = backprojection_edge(u1.y, shift.y);
  // Along x, row j holds columns [c0(j), c1(j)): those from x0.count to
  // x1.count - 1 (`inner`), column x1.count - 1 in the rows that take the
  // full count (`right_rows`) and column x0.count - 1 in those that take
  // count - 1 (`left_rows`; where the counts are equal, the one column in
  // the rows that do both).
  uint inner = backprojection_below(x1.count - 1u) & ~backprojection_below(x0.count);
  uint right_rows = x1.rows, left_rows = ~x0.rows & 0xffffu;
  uint right_column = x1.count - 1u, left_column = max(x0.count, 1u) - 1u;
  if (x0.count == x1.count) {
    right_rows &= left_rows;
    left_rows = 0u;
  }
  // Along y, the same with rows and columns swapped: rows y0.count to
  // y1.count - 2 whole, row y1.count - 1 in the columns `top`, row
  // y0.count - 1 in the columns `bottom`.
  uint whole_rows = backprojection_below(y1.count - 1u) & ~backprojection_below(y0.count);
  uint top_row = y1.count - 1u, top = y1.rows;
  uint bottom_row = max(y0.count, 1u) - 1u, bottom = ~y0.rows & 0xffffu;
  if (y0.count == y1.count) {
    top &= bottom;
    bottom = 0u;
  }
  // Word w holds rows 2w (bits 0-15) and 2w + 1 (bits 16-31): a row mask's
  // bits 2w and 2w + 1 moved to bits 0 and 16.
  uvec4 top_word = uvec4(top << (16u * (top_row & 1u)));
  uvec4 bottom_word = uvec4(bottom << (16u * (bottom_row & 1u)));
  for (uint half_index = 0u; half_index < 2u; ++half_index) {
    uvec4 w = uvec4(0u, 1u, 2u, 3u) + 4u * half_index;
    uvec4 r = uvec4(right_rows) >> (2u * w), l = uvec4(left_rows) >> (2u * w);
    uvec4 f = uvec4(whole_rows) >> (2u * w);
    uvec4 x = uvec4(inner | inner << 16u) | ((r & 1u) | (r & 2u) << 15u) << right_column |
              ((l & 1u) | (l & 2u) << 15u) << left_column;
    uvec4 y = (f & 1u) * 0xffffu | (f & 2u) * 0x7fff8000u |
              mix(uvec4(0u), top_word, equal(w, uvec4(top_row >> 1u))) |
              mix(uvec4(0u), bottom_word, equal(w, uvec4(bottom_row >> 1u)));
    if (half_index == 0u) {
      low |= x & y;
    } else {
      high |= x & y;
    }
  }
}

// What a lookup knows of its receiver, shared by its patches.
struct BackprojectionReceiver {
  vec2 center;          // map position, texels
  float z;              // biased z-bar at the lookup
  vec2 gradient;        // z-bar per texel of the receiver's plane
  vec3 p;               // view space
  vec3 n;               // view-space normal of the receiver's triangle
  vec3 shading_n;       // view-space shading normal: the horizon the source is weighed against
  float plane_slack;    // sine: BACKPROJECTION_PLANE_SLACK
  float receiver;       // 1 / d_r (perspective) or d_r (orthographic): backprojection_k()
  // The side of the square on the view's x-y plane that the source's grid
  // of points spans: source_width, or for a point light's sphere the
  // wider square around its image seen from the receiver
  // (backprojection_sphere_width()).
  float width;
  bool sphere;          // the source is that image of a sphere
  float scale;          // grid widths per texel and unit of k: depth_range.z / width
  // The rectangle of that square the 16 x 16 points span (centre xy, sides
  // zw, in its widths): the part above the receiver's horizon
  // (backprojection_horizon_window()).
  vec4 window;
  vec2 shift;           // the source grid's shift, in points
  // Whether a step between the hierarchy's cells is left open
  // (backprojection_joined()): the view has second surfaces, which hold
  // what lies behind a caster's edge, and the receiver lies in front of
  // them (behind them, a third surface the map lost may be in the way:
  // the default scene's spot 1.5 read 0.0050 without this condition,
  // 0.0047 with it).
  bool steps_open;
};

// Map offset (tangent units from the centre) of map point `texels`.
vec2 backprojection_tan(GpuShadowView view, vec2 texels) {
  return (texels - 0.5 * vec2(view.depth_range.w)) * view.depth_range.z;
}

// How far on the source, in source widths per texel of map offset, a
// patch at axial depth d projects: scale / k (backprojection_k()), so that
// its edge at offset a hides the source up to a times this; 0 where k <=
// 0. With k = 1/d - 1/d_r, scale / k = scale d / (1 - d / d_r): one
// division a patch. It grows with d (or scale / (d_r - d)).
float backprojection_depth_extent(GpuShadowView view, BackprojectionReceiver r, float d) {
  float k_times_d = view.perspective != 0 ? 1.0 - d * r.receiver : r.receiver - d;
  return k_times_d > 0.0 ? r.scale * (view.perspective != 0 ? d : 1.0) / k_times_d : 0.0;
}

// The extent (backprojection_depth_extent()) of a patch at z-bar
// `occluder` whose centre lies `mid` texels from the receiver's lookup; 0
// where it hides nothing: at or behind the receiver's plane, or k <= 0.
float backprojection_extent(GpuShadowView view, BackprojectionReceiver r, vec2 mid,
                            float occluder) {
  if (occluder >= r.z + dot(r.gradient, mid)) return 0.0;
  return backprojection_depth_extent(
      view, r, backprojection_depth(view, occluder, backprojection_tan(view, r.center + mid)));
}

// The least extent (backprojection_extent(), without its plane test) of a
// patch at z-bar `occluder` or behind it anywhere over map offsets [a0,
// a1] (texels from the lookup): the extent grows with the depth, so it is
// the one at `occluder`'s depth, made axial on a cube face at the
// offsets' farthest corner. 0 where that depth lies behind the receiver
// (k <= 0).
float backprojection_least_extent(GpuShadowView view, BackprojectionReceiver r, vec2 a0, vec2 a1,
                                  float occluder) {
  vec2 corner = max(abs(backprojection_tan(view, r.center + a0)),
                    abs(backprojection_tan(view, r.center + a1)));
  return backprojection_depth_extent(view, r, backprojection_depth(view, occluder, corner));
}

// Whether no patch over map offsets [a0, a1] can hide any of the source's
// points: each patch there hides [b0, b1] times its extent, its upper end
// reaching at most to b1 times a neighbour's extent
// (backprojection_hide_patch()), so none does where a0 times `least` (the
// least extent of the patches there) lies past the window's upper side
// (BackprojectionReceiver::window) on an axis, or a1 times `nearest` (the
// least extent of any patch or neighbour: the region's nearest depth)
// before its lower side. The extents have no upper bound, so a side on
// the far side of the source's centre counts as at it: a0 must be >= 0 to
// place the patch past an upper side, a1 <= 0 before a lower one. Of the
// cells' patches a wide region reads, 84 % lie off the source (the
// default scene's spot at 1.5); this skips their neighbours' reads.
bool backprojection_off_source(BackprojectionReceiver r, vec2 a0, vec2 a1, float least,
                               float nearest) {
  return any(greaterThanEqual(a0 * least, max(r.window.xy + 0.5 * r.window.zw, 0.0))) ||
         any(lessThanEqual(a1 * nearest, min(r.window.xy - 0.5 * r.window.zw, 0.0)));
}

// Whether the patch at z-bar `occluder` centred `mid` texels from the
// lookup lies above the receiver's tangent plane (within its
// plane_slack): one below it cannot block the light that reaches the
// receiver. dot(t, n) > -slack |t|, squared.
bool backprojection_above_plane(GpuShadowView view, BackprojectionReceiver r, vec2 mid,
                                float occluder) {
  vec2 u = backprojection_tan(view, r.center + mid);
  float d = backprojection_depth(view, occluder, u);
  vec3 to_occluder =
      (view.perspective != 0 ? vec3(u * d, -d) : vec3(r.p.xy + mid * view.depth_range.z, -d)) -
      r.p;
  float along = dot(to_occluder, r.n);
  return along > 0.0 ||
         along * along < r.plane_slack * r.plane_slack * dot(to_occluder, to_occluder);
}

// Hides the source points behind the patches over map offsets [a0, a1]
// (texels from the receiver's lookup) at every depth between two of
// extents `near_extent` and `far_extent` (backprojection_extent(), > 0):
// the bounding rectangle of their projections. Reaches to its blocking
// right and upper neighbours' projections of their shared edges (their
// extents `right` and `up`, 0 for none).
void backprojection_hide_span(BackprojectionReceiver r, vec2 a0, vec2 a1, float near_extent,
                              float far_extent, float right, float up, inout uvec4 low,
                              inout uvec4 high) {
  vec2 lo = min(a0 * near_extent, a0 * far_extent), hi = max(a1 * near_extent, a1 * far_extent);
  if (right > 0.0) hi.x = max(hi.x, a1.x * right);
  if (up > 0.0) hi.y = max(hi.y, a1.y * up);
  backprojection_hide(low, high, (lo - r.window.xy) / r.window.zw,
                      (hi - r.window.xy) / r.window.zw, r.shift);
}

// Hides the source points behind the patch over map offsets [a0, a1]
// (texels from the receiver's lookup) of extent `extent`
// (backprojection_extent(), > 0), reaching to its blocking right and upper
// neighbours' projections of their shared edges (their extents `right`
// and `up`, 0 for none).
void backprojection_hide_patch(BackprojectionReceiver r, vec2 a0, vec2 a1, float extent,
                               float right, float up, inout uvec4 low, inout uvec4 high) {
  backprojection_hide_span(r, a0, a1, extent, extent, right, up, low, high);
}

// Whether a surface may join neighbouring cells of the hierarchy's level
// level - 1 (2^level texels wide; level 0: texels) whose patches lie at
// z-bars `depth_a` and `depth_b`, so that the first's reach to the
// second's projection of their shared edge (Guennebaud et al. 2006's gap
// filling, backprojection_hide_patch()) stands for that surface: depths
// within BACKPROJECTION_STEP cell widths of each other, cells taken at
// least BACKPROJECTION_STEP_CELL texels wide. A larger step is a gap
// between two casters, left open where the map holds what lies behind the
// nearer one (BackprojectionReceiver::steps_open; not among the second
// surfaces' own cells). Elsewhere the wall it fills stands for surfaces
// the map lost: without second surfaces (an engine's maps, drawn once
// through ShadowMaps) the default scene's point light at 1.5 read 0.0137
// with its steps open, 0.0094 with the walls (RMSE, 640x360); with them
// on its cube faces as well, 0.0053. Over the default scene's box, the wall
// from the slab's edge down to the box hid the light that passes between
// them: the ground at the box's foot read 0.05 where the traced reference
// reads 0.2 (spot 1.5: RMSE 0.0059 -> 0.0047; sun 8.45 degrees: 0.0064 ->
// 0.0054).
bool backprojection_joined(GpuShadowView view, BackprojectionReceiver r, int layer, int level,
                           float depth_a, float depth_b) {
  if (!r.steps_open || layer == view.second_layer) return true;
  float near = min(depth_a, depth_b);
  float across = float(max(1 << level, BACKPROJECTION_STEP_CELL)) * view.depth_range.z *
                 (view.perspective != 0 ? linear_depth_of(view, near) : 1.0);
  return abs(depth_b - depth_a) * (view.depth_range.y - view.depth_range.x) <=
         BACKPROJECTION_STEP * across;
}

// Hides the source points behind the patch of the texel [a0, a0 + 1]
// (texels from the lookup) at z-bar `depth` of extent `extent`
// (backprojection_extent(); 0: none), if it lies above the receiver's
// plane, reaching to its right and upper neighbours (their z-bars and
// extents: `right`, `up`) where a surface may join them
// (backprojection_joined()).
void backprojection_texel_patch(GpuShadowView view, BackprojectionReceiver r, int layer, vec2 a0,
                                float depth, float extent, vec2 right, vec2 up, inout uvec4 low,
                                inout uvec4 high) {
  if (extent <= 0.0 || !backprojection_above_plane(view, r, a0 + 0.5, depth)) return;
  float reach_right = backprojection_joined(view, r, layer, 0, depth, right.x) ? right.y : 0.0;
  float reach_up = backprojection_joined(view, r, layer, 0, depth, up.x) ? up.y : 0.0;
  backprojection_hide_patch(r, a0, a0 + 1.0, extent, reach_right, reach_up, low, high);
}

// The extents (backprojection_extent()) of texels t and t + step at
// z-bars `first` and `second`: 0 outside the map (`size` texels).
vec2 backprojection_pair_extents(GpuShadowView view, BackprojectionReceiver r, ivec2 t,
                                 ivec2 step, float first, float second, ivec2 size) {
  vec2 a = vec2(t) - r.center + 0.5;
  return vec2(all(lessThan(t, size)) ? backprojection_extent(view, r, a, first) : 0.0,
              all(lessThan(t + step, size))
                  ? backprojection_extent(view, r, a + vec2(step), second)
                  : 0.0);
}

// Hides the source points behind the patches of texels [t0, t1] (inside
// the map; each reaching to its blocking right and upper neighbours where
// a surface may join them: backprojection_texel_patch()), two by two:
// GATHER reads a texel (w), its right (z), upper (x) and upper right (y)
// neighbours (textureGather at its upper right corner;
// depth_map_hooks.glsl). A 2 x 2 whose texels all lie behind the
// receiver's plane hides nothing and is left after that one read; the
// others read the column to their right and the row above them as well,
// where their texels need them as neighbours.
#define BACKPROJECTION_TEXEL_PATCHES_DEFINE(NAME, MAPS, TEXELS, GATHER)                            \
  void NAME(MAPS depth_maps, int layer, GpuShadowView view, BackprojectionReceiver r,              \
            ivec2 t0, ivec2 t1, inout uvec4 low, inout uvec4 high) {                               \
    ivec2 size = TEXELS(depth_maps, layer);                                                        \
    for (int ty = t0.y; ty <= t1.y; ty += 2) {                                                     \
      for (int tx = t0.x; tx <= t1.x; tx += 2) {                                                   \
        ivec2 t = ivec2(tx, ty);                                                                   \
        vec4 g = GATHER(depth_maps, layer, t);                                                     \
        /* Lower row (x: left, y: right) and upper row. */                                         \
        vec2 lower = backprojection_pair_extents(view, r, t, ivec2(1, 0), g.w, g.z, size);         \
        vec2 upper = backprojection_pair_extents(view, r, t + ivec2(0, 1), ivec2(1, 0), g.x,       \
                                                 g.y, size);                                       \
        /* The region's own texels; those past t1 are only neighbours. */                          \
        bvec2 second = lessThanEqual(t + 1, t1);                                                   \
        vec4 own = vec4(lower.x, second.x ? lower.y : 0.0, second.y ? upper.x : 0.0,               \
                        all(second) ? upper.y : 0.0);                                              \
        if (all(equal(own, vec4(0.0)))) continue;                                                  \
        /* The column to the right and the row above: extents and depths. */                       \
        vec2 right = vec2(0.0), above = vec2(0.0);                                                 \
        vec2 right_depth = vec2(1.0), above_depth = vec2(1.0);                                     \
        if (own.y > 0.0 || own.w > 0.0) {                                                          \
          vec4 h = GATHER(depth_maps, layer, t + ivec2(2, 0));                                     \
          right = backprojection_pair_extents(view, r, t + ivec2(2, 0), ivec2(0, 1), h.w, h.x,     \
                                              size);                                               \
          right_depth = h.wx;                                                                      \
        }                                                                                          \
        if (own.z > 0.0 || own.w > 0.0) {                                                          \
          vec4 h = GATHER(depth_maps, layer, t + ivec2(0, 2));                                     \
          above = backprojection_pair_extents(view, r, t + ivec2(0, 2), ivec2(1, 0), h.w, h.z,     \
                                              size);                                               \
          above_depth = h.wz;                                                                      \
        }                                                                                          \
        vec2 a = vec2(t) - r.center;                                                               \
        backprojection_texel_patch(view, r, layer, a, g.w, own.x, vec2(g.z, lower.y),              \
                                   vec2(g.x, upper.x), low, high);                                 \
        backprojection_texel_patch(view, r, layer, a + vec2(1.0, 0.0), g.z, own.y,                 \
                                   vec2(right_depth.x, right.x), vec2(g.y, upper.y), low, high);   \
        backprojection_texel_patch(view, r, layer, a + vec2(0.0, 1.0), g.x, own.z,                 \
                                   vec2(g.y, upper.y), vec2(above_depth.x, above.x), low, high);   \
        backprojection_texel_patch(view, r, layer, a + 1.0, g.y, own.w,                            \
                                   vec2(right_depth.y, right.y), vec2(above_depth.y, above.y),     \
                                   low, high);                                                     \
      }                                                                                            \
    }                                                                                              \
  }
BACKPROJECTION_TEXEL_PATCHES_DEFINE(backprojection_texel_patches, sampler2DArray,
                                    shadow_map_texels, shadow_map_gather)

// The window of the source's grid (BackprojectionReceiver::window): the
// bounding rectangle of the part of the square (r.width wide) above the
// receiver's shading horizon, where the rays that count meet it
// (backprojection_lit_fraction() weighs the others 0), so that all 256
// points fall where they count; the whole square where none of it lies
// above. The square's corners above the horizon and the horizon's
// crossings of its sides bound it. Near a terminator only a sliver of the
// source is above, and the few points of the whole square in it read it
// coarsely: the default scene's sphere under its slab, seen close up along
// its terminator (source 1.5, 200x150), RMSE 0.0181 -> 0.0096; at
// 1280x720, 2048^2 maps, the default scene's spot at 1.5 0.00329 ->
// 0.00320, its point light at 1.5 0.00400 -> 0.00388, the foliage's spot
// at 1.5 0.0146 -> 0.0144, the bunny's cells within 0.3 %.
void backprojection_horizon_window(GpuShadowView view, inout BackprojectionReceiver r) {
  // Above where dot(n, (q width, 0) - p) > 0: dot(a, q) > b.
  vec3 p = view.perspective != 0 ? r.p : vec3(0.0, 0.0, -1.0);
  vec2 a = r.shading_n.xy * r.width;
  float b = dot(r.shading_n, p);
  vec2 lo = vec2(0.5), hi = vec2(-0.5);
  for (int k = 0; k < 4; ++k) {
    vec2 corner = vec2(k & 1, k >> 1) - 0.5;
    if (dot(a, corner) >= b) {
      lo = min(lo, corner);
      hi = max(hi, corner);
    }
    // The horizon's crossing of side k: x = -+1/2 (k < 2) or y = -+1/2.
    int axis = k >> 1;
    float side = float(k & 1) - 0.5;
    if (a[1 - axis] != 0.0) {
      float along = (b - a[axis] * side) / a[1 - axis];
      if (abs(along) <= 0.5) {
        vec2 q = axis == 0 ? vec2(side, along) : vec2(along, side);
        lo = min(lo, q);
        hi = max(hi, q);
      }
    }
  }
  r.window = all(lessThan(lo, hi)) ? vec4(0.5 * (lo + hi), max(hi - lo, vec2(1.0 / 256.0)))
                                   : vec4(0.0, 0.0, 1.0, 1.0);
}

// A point light's sphere (radius R = source_width / 2, its centre the
// view's eye) as a receiver at p (view space) sees it: the rays from p
// that meet it cross the view's plane z = 0 where |l x p| <= R |l - p|
// (the ray passes within R of the centre), an ellipse stretched along the
// direction to the receiver. A receiver theta off the view's axis sees it
// reach R / cos(theta + beta) from the centre, sin beta = R / |p| (the
// tangent rays in the plane of the axis and p), so the grid spans a square
// that wide (returned). The disc of radius R on the plane, which stood for
// it before, hid 23 % too little of a receiver 40 degrees off a face's
// axis.
float backprojection_sphere_width(GpuShadowView view, vec3 p) {
  float distance = length(p);
  float sin_beta = min(0.5 * view.source_width / distance, 1.0);
  float cos_theta = -p.z / distance;
  float sin_theta = length(p.xy) / distance;
  float cos_sum = cos_theta * sqrt(1.0 - sin_beta * sin_beta) - sin_theta * sin_beta;
  // A receiver nearly touching the sphere sees it past the plane's
  // horizon: the grid stops at ten times the sphere's width.
  return view.source_width / max(cos_sum, 0.1);
}

// The receiver of lookup s (biased z-bar z, receiver-plane gradient
// `gradient` per texel, the triangle's world normal `normal`, the shading
// normal `shading_normal` whose horizon weighs the source, as the traced
// reference does) in view `view`, whose map is `size` texels wide, under
// its source: a sphere (`sphere`: a point light's,
// backprojection_sphere_width()) or the view's square or disc; `pixel`
// seeds the shift of the source's grid.
BackprojectionReceiver backprojection_receiver(GpuShadowView view, ShadowLookup s, float z,
                                               vec2 gradient, vec3 normal,
                                               vec3 shading_normal, bool sphere, ivec2 size,
                                               ivec2 pixel) {
  BackprojectionReceiver r;
  r.center = s.uv * vec2(size);
  r.z = z;
  r.gradient = gradient;
  r.p = (view.view * vec4(s.position, 1.0)).xyz;
  r.n = normalize(mat3(view.view) * normal);
  r.shading_n = normalize(mat3(view.view) * shading_normal);
  r.plane_slack = max(BACKPROJECTION_PLANE_SLACK, 2.0 * length(cross(r.n, r.shading_n)));
  // A receiver whose triangle faces away from the source's centre (a
  // smooth surface past its terminator) sees only the part of the source
  // above its horizon, and the rays to it run behind its plane as the map
  // sees it: the plane's cut, which keeps what lies in front of the plane,
  // would drop every blocker of that part (the default scene's sphere
  // under the slab read lit along its terminator where the traced
  // reference reads 0). There the cut is at the receiver's own depth, and
  // backprojection_above_plane() keeps the half-space above the plane.
  vec3 to_source = view.perspective != 0 ? -r.p : vec3(0.0, 0.0, 1.0);
  if (dot(r.n, to_source) <= 0.0) r.gradient = vec2(0.0);
  float d_r = -r.p.z;
  r.receiver = view.perspective != 0 ? 1.0 / d_r : d_r;
  r.sphere = sphere;
  r.width = sphere ? backprojection_sphere_width(view, r.p) : view.source_width;
  r.scale = view.depth_range.z / r.width;
  backprojection_horizon_window(view, r);
  r.shift = accumulate_hash(pixel, 977).xy;
  r.steps_open = false;
  return r;
}

// Whether the grid's point (x, y) on the view's plane lies on the source:
// for a sphere, |l x p|^2 <= R^2 |l - p|^2 (backprojection_sphere_width();
// `d2` = |l - p|^2, `radius2` = R^2); otherwise inside the circle of
// radius^2 `radius2` (the sun's disc of directions; a square's is
// infinite).
bool backprojection_on_source(BackprojectionReceiver r, vec3 p, float radius2, float x, float y,
                              float d2) {
  if (r.sphere) {
    float across = x * p.y - y * p.x;
    return p.z * p.z * (x * x + y * y) + across * across <= radius2 * d2;
  }
  return x * x + y * y <= radius2;
}

// The lit fraction of the source points the mask (low, high) leaves
// visible. `disc`: the source is a disc (a point light's sphere, the sun).
float backprojection_lit_fraction(GpuShadowView view, BackprojectionReceiver r, uvec4 low,
                                  uvec4 high, bool disc) {
  // Nothing hidden is lit and everything hidden is dark, whatever the
  // weights (no need to weigh the 256 points).
  if (all(equal(low | high, uvec4(0u)))) return 1.0;
  if (all(equal(low & high, uvec4(0xffffffffu)))) return 0.0;
  float width = r.width;
  // Each point weighs cos theta_receiver dw, dw its solid angle: for a
  // point on the source's plane, facing the view's -z, (d_r / |t|) dA /
  // |t|^2 (d_r cancels in the ratio); for a direction (x, y, 1) of the
  // sun's, dA / |t|^3. Both are (n . t) / |t|^4, t = (x, y, 0) - p with p
  // the receiver (perspective) or (0, 0, -1). A disc keeps the points
  // inside its circle, a sphere those inside its image
  // (backprojection_on_source()).
  vec3 p = view.perspective != 0 ? r.p : vec3(0.0, 0.0, -1.0);
  vec3 n = r.shading_n;
  float radius2 = disc ? 0.25 * view.source_width * view.source_width : 1.0e30;
  vec2 origin = (r.window.xy - 0.5 * r.window.zw) * width;
  vec2 step = r.window.zw * (width / float(BACKPROJECTION_SIDE));
  // Point (i, j) at (x_i(j), y_j(i)) (backprojection_offset()) of the
  // window: each column's y-offsets, and the x of each row's first point.
  float column_y[BACKPROJECTION_SIDE];
  for (int i = 0; i < BACKPROJECTION_SIDE; ++i) {
    column_y[i] = origin.y + backprojection_offset(i, r.shift.y) * step.y;
  }
  float total = 0.0, lit = 0.0;
  for (int j = 0; j < BACKPROJECTION_SIDE; ++j) {
    uint word = j < 8 ? low[j >> 1] : high[(j - 8) >> 1];
    uint row = word >> uint(16 * (j & 1));
    float x0 = origin.x + backprojection_offset(j, r.shift.x) * step.x;
    float y0 = float(j) * step.y;
    for (int i = 0; i < BACKPROJECTION_SIDE; ++i) {
      float x = x0 + float(i) * step.x, y = y0 + column_y[i];
      vec3 t = vec3(x, y, 0.0) - p;
      float d2 = dot(t, t);
      float weight = backprojection_on_source(r, p, radius2, x, y, d2)
                         ? max(dot(n, t), 0.0) / (d2 * d2)
                         : 0.0;
      total += weight;
      lit += ((row >> uint(i)) & 1u) == 0u ? weight : 0.0;
    }
  }
  if (total > 0.0) return lit / total;
  // Where the horizon leaves a sliver of the source that no point
  // reaches, the points nearest below it stand for the sliver, each
  // weighed by exp(BACKPROJECTION_SLIVER_SHARPNESS cos theta_receiver)
  // (the reference judges such a pixel by its own points in the sliver).
  // The one nearest point alone, as before, read lit a pixel on the
  // default scene's torus that the reference and the converged frame read
  // dark (the 8.45 degree sun, 1280x720: a sixth of the image's squared
  // error, RMSE 0.00307 -> 0.00285); the image's three other slivers stay
  // lit, as the reference reads them.
  float top = -2.0, weights = 0.0, lit_weights = 0.0;
  for (int j = 0; j < BACKPROJECTION_SIDE; ++j) {
    uint word = j < 8 ? low[j >> 1] : high[(j - 8) >> 1];
    uint row = word >> uint(16 * (j & 1));
    float x0 = origin.x + backprojection_offset(j, r.shift.x) * step.x;
    for (int i = 0; i < BACKPROJECTION_SIDE; ++i) {
      float x = x0 + float(i) * step.x, y = float(j) * step.y + column_y[i];
      vec3 t = vec3(x, y, 0.0) - p;
      if (!backprojection_on_source(r, p, radius2, x, y, dot(t, t))) continue;
      // Weighed relative to the nearest point so far (`top`), so that no
      // weight overflows or all vanish.
      float cos_receiver = dot(n, t) * inversesqrt(dot(t, t));
      if (cos_receiver > top) {
        float rescale = exp(BACKPROJECTION_SLIVER_SHARPNESS * (top - cos_receiver));
        weights *= rescale;
        lit_weights *= rescale;
        top = cos_receiver;
      }
      float w = exp(BACKPROJECTION_SLIVER_SHARPNESS * (cos_receiver - top));
      weights += w;
      lit_weights += ((row >> uint(i)) & 1u) == 0u ? w : 0.0;
    }
  }
  return weights > 0.0 ? lit_weights / weights : 1.0;
}

// The reach (backprojection_hide_patch()'s `right` or `up`) of a patch at
// z-bar `occluder` towards its neighbour at z-bar `neighbour`, centred
// `centre` texels from the lookup: that neighbour's extent where a surface
// may join them (backprojection_joined()), else 0.
float backprojection_reach(GpuShadowView view, BackprojectionReceiver r, int layer, int level,
                           float occluder, float neighbour, vec2 centre) {
  return backprojection_joined(view, r, layer, level, occluder, neighbour)
             ? backprojection_extent(view, r, centre, neighbour)
             : 0.0;
}

// The z-bar of the patch that backprojection_cell_patch() draws for a
// cell of the hierarchy (its nearest, farthest and mean z-bars `m`)
// centred `centre` texels from the lookup, wherever it is wholly in front
// of the receiver's plane: its texels' mean; a cut cell, read finer, at
// its nearest. A neighbour reaches to the patch's own projection of their
// shared side: reaching to its nearest depth's (the projection nearest
// the source's centre) left a crack between them on the side of the
// receiver's lookup away from the source's centre, where the source
// showed through in the middle of an umbra (the default scene's torus
// under the 8.45 degree sun with --tight-cascades, on the ground: 5 % of
// the source). With the flat 2 x 2s' patches over their depths' span
// (shadow_backprojection()), RMSE at 1280x720: that sun 0.00292 ->
// 0.00274; the default scene's spot at 1.5 0.00320 -> 0.00303 (this alone
// 0.00323), its point light at 1.5 0.00388 -> 0.00373, the foliage's spot
// at 1.5 0.01442 -> 0.01401; no cell of the study worse.
float backprojection_cell_depth(BackprojectionReceiver r, vec3 m, vec2 centre) {
  return m.y < r.z + dot(r.gradient, centre) ? m.z : m.x;
}

// Hides the source points behind the box over the sub-cells `cols` x
// `rows` (bits 0-3: the columns, the rows, from the lower left) of cell c
// of the hierarchy's level level - 1 (its corners a0, a1 texels from the
// lookup, `cells` of them; 4 x 4 sub-cells `sub` texels wide) at z-bar
// `occluder`, reaching to the right and upper neighbour cells'
// projections of their shared sides where the box touches them.
void backprojection_cell_box(sampler2DArray hierarchy, int layer, GpuShadowView view,
                             BackprojectionReceiver r, int level, ivec2 cells, ivec2 c, vec2 a0,
                             vec2 a1, float sub, uint cols, uint rows, float occluder,
                             inout uvec4 low, inout uvec4 high) {
  ivec2 first = ivec2(findLSB(cols), findLSB(rows)), last = ivec2(findMSB(cols), findMSB(rows));
  bvec2 touches = equal(last, ivec2(3));
  vec2 b0 = a0 + sub * vec2(first);
  vec2 b1 = mix(a0 + sub * vec2(last + 1), a1, touches);
  vec2 centre = 0.5 * (b0 + b1);
  float extent = backprojection_extent(view, r, centre, occluder);
  if (extent <= 0.0 || !backprojection_above_plane(view, r, centre, occluder)) return;
  // The neighbours' nearest depths, at their centres as if as wide.
  vec2 mid = 0.5 * (a0 + a1);
  float right = 0.0, up = 0.0;
  if (c.x + 1 < cells.x && touches.x) {
    vec2 centre = vec2(a1.x + 0.5 * (a1.x - a0.x), mid.y);
    vec3 m = texelFetch(hierarchy, ivec3(c.x + 1, c.y, layer), level - 1).rgb;
    SHADOW_FETCHED(1);
    right = backprojection_reach(view, r, layer, level, occluder,
                                 backprojection_cell_depth(r, m, centre), centre);
  }
  if (c.y + 1 < cells.y && touches.y) {
    vec2 centre = vec2(mid.x, a1.y + 0.5 * (a1.y - a0.y));
    vec3 m = texelFetch(hierarchy, ivec3(c.x, c.y + 1, layer), level - 1).rgb;
    SHADOW_FETCHED(1);
    up = backprojection_reach(view, r, layer, level, occluder,
                              backprojection_cell_depth(r, m, centre), centre);
  }
  backprojection_hide_patch(r, b0, b1, extent, right, up, low, high);
}

// A cell of the hierarchy as 4 x 4 sub-cells: those in front of the
// receiver's plane (a row of 4 bits each; rows.x: the lowest), and the
// depths of the patches over them: over the lower two rows, the upper
// two, and all four.
struct BackprojectionCellFront {
  uvec4 rows;
  vec2 halves;
  float whole;
};

// The receiver's plane (z-bar) at the 2 x 2 points `q`, q + (step, 0),
// q + (0, step) and q + step (texels from the lookup).
vec4 backprojection_planes(BackprojectionReceiver r, vec2 q, float step) {
  return r.z + vec4(dot(r.gradient, q), dot(r.gradient, q + vec2(step, 0.0)),
                    dot(r.gradient, q + vec2(0.0, step)), dot(r.gradient, q + step));
}

// Which of the 2 x 2 texels from `lower_left` lie in front of the
// receiver's plane (x: the lower row, y: the upper, 2 bits each), their
// z-bars and their count added to `sum`.
uvec2 backprojection_front_texels(sampler2DArray depth_maps, int layer, BackprojectionReceiver r,
                                  ivec2 lower_left, ivec2 size, inout vec2 sum) {
  ivec2 t = min(lower_left, size - 2);
  vec4 g = textureGather(depth_maps, vec3(vec2(t + 1) / vec2(size), float(layer)));
  SHADOW_FETCHED(1);
  // Gathered: (0, 1), (1, 1), (1, 0), (0, 0).
  vec4 planes = backprojection_planes(r, vec2(t) + 0.5 - r.center, 1.0).zwyx;
  bvec4 front = lessThan(g, planes);
  sum += vec2(dot(g, vec4(front)), dot(vec4(front), vec4(1.0)));
  return uvec2(uint(front.w) | uint(front.z) << 1u, uint(front.x) | uint(front.y) << 1u);
}

// A cut cell 4 texels wide (level 2), texel by texel: its 16 texels in
// four gathers, each patch at the mean depth of the texels in front under
// it.
BackprojectionCellFront backprojection_cut_texels(sampler2DArray depth_maps, int layer,
                                                  BackprojectionReceiver r, ivec2 t0,
                                                  ivec2 size) {
  vec2 lower = vec2(0.0), upper = vec2(0.0);
  uvec2 ll = backprojection_front_texels(depth_maps, layer, r, t0, size, lower);
  uvec2 lr = backprojection_front_texels(depth_maps, layer, r, t0 + ivec2(2, 0), size, lower);
  uvec2 ul = backprojection_front_texels(depth_maps, layer, r, t0 + ivec2(0, 2), size, upper);
  uvec2 ur = backprojection_front_texels(depth_maps, layer, r, t0 + 2, size, upper);
  return BackprojectionCellFront(uvec4(ll | lr << 2u, ul | ur << 2u),
                                 vec2(lower.x / max(lower.y, 1.0), upper.x / max(upper.y, 1.0)),
                                 (lower.x + upper.x) / max(lower.y + upper.y, 1.0));
}

// A cut cell of any other level as its quarters, each in front where its
// centre texel is (the one up and right of its centre where the quarter
// is an even number of texels wide), the patches at the nearest of their
// depths.
BackprojectionCellFront backprojection_cut_quarters(sampler2DArray depth_maps, int layer,
                                                    BackprojectionReceiver r, ivec2 t0,
                                                    int level, ivec2 size) {
  int half_cell = 1 << (level - 1);
  ivec2 t = t0 + (half_cell >> 1);
  ivec2 across = ivec2(half_cell, 0), above = ivec2(0, half_cell);
  // x: lower left, y: lower right, z: upper left, w: upper right
  vec4 d = vec4(texelFetch(depth_maps, ivec3(min(t, size - 1), layer), 0).r,
                texelFetch(depth_maps, ivec3(min(t + across, size - 1), layer), 0).r,
                texelFetch(depth_maps, ivec3(min(t + above, size - 1), layer), 0).r,
                texelFetch(depth_maps, ivec3(min(t + half_cell, size - 1), layer), 0).r);
  SHADOW_FETCHED(4);
  vec4 planes = backprojection_planes(r, vec2(t) + 0.5 - r.center, float(half_cell));
  bvec4 front = lessThan(d, planes);
  d = mix(vec4(1.0e30), d, front);
  uvec4 quarter_rows = uvec4(front) * uvec4(3u, 12u, 3u, 12u);
  uint lower = quarter_rows.x | quarter_rows.y, upper = quarter_rows.z | quarter_rows.w;
  vec2 halves = min(d.xz, d.yw);
  return BackprojectionCellFront(uvec4(lower, lower, upper, upper), halves,
                                 min(halves.x, halves.y));
}

// Hides the source points behind cell c of the hierarchy's level level - 1
// (2^level texels wide, `cells` of them). A cell whose depths all lie in
// front is a patch at the mean depth of its texels (the hierarchy's). A
// cell the receiver's plane cuts (a silhouette with what lies behind the
// receiver) is read finer: one 4 texels wide texel by texel, each patch
// at the mean depth of the texels in front under it; one of another
// width as its quarters, each as its centre texel, each patch at the
// nearest of their depths. Over those in front: one patch where the
// lower and the upper half of the cell hold the same columns (or one
// holds none), else one over each half, reaching to a neighbour only
// across a side it touches.
//
// The cells' patches at the nearest depth of their texels drew each
// cell's projection towards the source's centre (docs/rendering.md, "Why
// cells at their nearest depth widen a penumbra, and the mean depth that
// keeps them in place"), and quarters, judged by a texel up and right of
// their centre, moved a silhouette by up to a quarter of a cell: a
// straight edge's penumbra read from cells 4 texels wide, binned RMS at
// worst 0.0046, now 0.0005. RMSE at 640x360, the
// quarters at the nearest depth -> texel by texel -> at the mean depths:
// default scene, spot 1.5 0.00394 -> 0.00334 -> 0.00305, point 1.5 0.00432
// -> 0.00409 -> 0.00384; foliage, spot 1.5 0.0149 -> 0.0153 -> 0.0152,
// point 1.5 0.0185 -> 0.0186 -> 0.0180; the other cells of the study
// within 0.0001. The lighting pass took 1.19 and 1.21 times as long
// (llvmpipe, which runs a branch for all eight pixels it shades together
// when one takes it). The mean depth where it did not help: a cell 2
// texels wide, its quarters being its texels (spot 1.5 0.00313), a merged
// 2 x 2 of cells (0.00335), a neighbour's depth in the reach to it
// (0.00330); two patches over every cut cell 4 texels wide, 0.00307.
void backprojection_cell_patch(sampler2DArray depth_maps, sampler2DArray hierarchy, int layer,
                               GpuShadowView view, BackprojectionReceiver r, int level,
                               ivec2 cells, ivec2 c, float nearest_extent, inout uvec4 low,
                               inout uvec4 high) {
  ivec2 size = textureSize(depth_maps, 0).xy;
  vec2 a0 = vec2(c << level) - r.center;
  vec2 a1 = vec2(mix(ivec2(c + 1) << level, size, equal(c, cells - 1))) - r.center;
  vec3 m = texelFetch(hierarchy, ivec3(c, layer), level - 1).rgb;  // nearest, farthest, mean
  SHADOW_FETCHED(1);
  float plane = r.z + dot(r.gradient, 0.5 * (a0 + a1));
  if (m.x >= plane ||
      backprojection_off_source(r, a0, a1, backprojection_least_extent(view, r, a0, a1, m.x),
                                nearest_extent)) {
    return;
  }
  BackprojectionCellFront f = BackprojectionCellFront(uvec4(15u), vec2(m.z), m.z);
  if (m.y >= plane) {
    f = level == 2 ? backprojection_cut_texels(depth_maps, layer, r, c << level, size)
                   : backprojection_cut_quarters(depth_maps, layer, r, c << level, level, size);
  }
  // The patches, written out, not looped: llvmpipe ends every loop of a
  // shader invocation after 65535 iterations of them all
  // (include/penumbra/settings.hpp, kMaxBackprojectionCells).
  uint lower = f.rows.x | f.rows.y, upper = f.rows.z | f.rows.w;
  if ((lower | upper) == 0u) return;
  bool split = lower != upper && lower != 0u && upper != 0u;
  uint rows = uint(f.rows.x != 0u) | uint(f.rows.y != 0u) << 1u | uint(f.rows.z != 0u) << 2u |
              uint(f.rows.w != 0u) << 3u;
  float sub = 0.25 * float(1 << level);
  backprojection_cell_box(hierarchy, layer, view, r, level, cells, c, a0, a1, sub,
                          split ? lower : lower | upper, split ? rows & 3u : rows,
                          split ? f.halves.x : f.whole, low, high);
  if (split) {
    backprojection_cell_box(hierarchy, layer, view, r, level, cells, c, a0, a1, sub, upper,
                            rows & 12u, f.halves.y, low, high);
  }
}

// The lower left of the 2 x 2 cells of the hierarchy's level level - 1
// (2^level texels wide, `cells` of them) around the receiver's lookup.
ivec2 backprojection_near_cells(BackprojectionReceiver r, int level, ivec2 cells) {
  return clamp(ivec2(floor(r.center / float(1 << level) - 0.5)), ivec2(0),
               max(cells - 2, ivec2(0)));
}

// Hides the source points behind the 2 x 2 cells of 2^level texels around
// the receiver's lookup (backprojection_near_cells()), finer the nearer:
// the 2 x 2 of cells BACKPROJECTION_REFINE_LEVEL wide (or `level`, if
// finer) as texels, then each wider level's 2 x 2 up to `level`'s as the
// cells of the level below it (backprojection_cell_patch()), those read
// already left: 16 x 16 texels, and 12 cells a level (up to 21 where a
// row's last cell takes an odd remainder). A contact a few texels from
// the receiver lies in a cell of its own, which the receiver's plane
// cuts, so it is read finer there. With `level`'s own cells here, the
// default scene's spot light 6 wide (640x360) read the ground along the
// box's lit foot as umbra where the reference reads 0.93 lit (RMSE
// 0.0206; so, 0.0143), and with --backprojection-cells 16 its spot at
// 1.5 did the same (0.0180; so, 0.0049). Texels alone up to `level`'s
// 2 x 2 read 0.0142 and 0.0045, at four times the gathers a level.
void backprojection_near_patches(sampler2DArray depth_maps, sampler2DArray hierarchy, int layer,
                                 GpuShadowView view, BackprojectionReceiver r, int level,
                                 float nearest_extent, inout uvec4 low, inout uvec4 high) {
  ivec2 size = textureSize(depth_maps, 0).xy;
  int finest = min(level, BACKPROJECTION_REFINE_LEVEL);
  ivec2 cells = backprojection_cells(hierarchy, finest - 1);
  ivec2 inner = backprojection_near_cells(r, finest, cells);
  ivec2 t0 = inner << finest;
  ivec2 t1 = mix(t0 + (2 << finest), size, equal(inner + 1, cells - 1)) - 1;
  backprojection_texel_patches(depth_maps, layer, view, r, t0, t1, low, high);
  for (int ring = finest; ring < level; ++ring) {
    // Level ring + 1's 2 x 2 in cells of `ring` (the last cell of a row
    // or column takes an odd remainder), but `inner`, read above.
    ivec2 wider_cells = backprojection_cells(hierarchy, ring);
    ivec2 outer = backprojection_near_cells(r, ring + 1, wider_cells);
    ivec2 c0 = outer << 1;
    ivec2 c1 = min(mix(c0 + 3, cells - 1, equal(outer + 1, wider_cells - 1)), cells - 1);
    ivec2 n = c1 - c0 + 1;
    for (int k = 0; k < n.x * n.y; ++k) {
      ivec2 c = c0 + ivec2(k % n.x, k / n.x);
      if (all(greaterThanEqual(c, inner)) && all(lessThanEqual(c, inner + 1))) continue;
      backprojection_cell_patch(depth_maps, hierarchy, layer, view, r, ring, cells, c,
                                nearest_extent, low, high);
    }
    cells = wider_cells;
    inner = outer;
  }
}

// A cube face's axis and up vector: twins of cube_face_axis() and
// cube_face_up() in src/shadow/cube_views.cpp, whose glm::lookAt() makes
// each face's view.
vec3 backprojection_cube_axis(int face) {
  vec3 axis = vec3(0.0);
  axis[face >> 1] = (face & 1) == 0 ? 1.0 : -1.0;
  return axis;
}
vec3 backprojection_cube_up(int face) {
  return face == 2 ? vec3(0.0, 0.0, 1.0) : face == 3 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, -1.0, 0.0);
}

// The first layer of the cube whose face `view` is (layer `layer`): the
// faces' views are a point light's six, in cube_face()'s order.
int backprojection_cube_first(GpuShadowView view, int layer) {
  return layer - cube_face(-vec3(view.view[0][2], view.view[1][2], view.view[2][2]));
}

// The hierarchy's cell of level `level` (cells 2^(level + 1) texels wide)
// that holds the direction of map point `p` (texels) of cube face `view`
// past the face's map: the face that direction falls in (its layer from
// `first`), at the same texel size. A face stores distances from the
// light, the same in every face, so its z-bars read as the view's own.
vec3 backprojection_cube_cell(sampler2DArray hierarchy, GpuShadowView view, int first, vec2 p,
                              int level) {
  vec3 dir = transpose(mat3(view.view)) * vec3(backprojection_tan(view, p), -1.0);
  int face = cube_face(dir);
  vec3 f = backprojection_cube_axis(face);
  vec3 side = normalize(cross(f, backprojection_cube_up(face)));
  vec3 up = cross(side, f);
  vec2 tangent = vec2(dot(side, dir), dot(up, dir)) / dot(f, dir);
  vec2 q = tangent / view.depth_range.z + 0.5 * view.depth_range.w;
  ivec2 cells = backprojection_cells(hierarchy, level);
  ivec2 c = clamp(ivec2(floor(q)) >> (level + 1), ivec2(0), cells - 1);
  SHADOW_FETCHED(1);
  return texelFetch(hierarchy, ivec3(c, first + face), level).rgb;
}

// The nearest and farthest depth, over a 4 x 4 grid of samples of the
// texels [lo, hi] of cube face `view` that lie past its map (`size`),
// of the other faces' hierarchy cells about as wide as the samples'
// spacing; (1e30, -1e30) where none does.
vec2 backprojection_cube_bounds(sampler2DArray hierarchy, GpuShadowView view, int first, ivec2 lo,
                                ivec2 hi, ivec2 size) {
  vec2 bounds = vec2(1.0e30, -1.0e30);
  if (all(greaterThanEqual(lo, ivec2(0))) && all(lessThan(hi, size))) return bounds;
  vec2 spacing = vec2(hi - lo + 1) / 4.0;
  int level = clamp(findMSB(int(max(spacing.x, spacing.y))), 0,
                    backprojection_levels(hierarchy) - 1);
  for (int k = 0; k < 16; ++k) {
    vec2 p = vec2(lo) + (vec2(k & 3, k >> 2) + 0.5) * spacing;
    if (all(greaterThanEqual(p, vec2(0.0))) && all(lessThan(p, vec2(size)))) continue;
    vec2 m = backprojection_cube_cell(hierarchy, view, first, p, level).rg;
    bounds = vec2(min(bounds.x, m.x), max(bounds.y, m.y));
  }
  return bounds;
}

// Lit fraction of the receiver of lookup s (biased z-bar z, receiver-plane
// gradient `gradient` per texel, its triangle's world normal `normal`,
// which keeps its own surface's patches out, and the shading normal
// `shading_normal`, whose horizon weighs the source as the traced
// reference does: docs/comparing.md, "The terminator model") in view `view`
// (layer `layer` of depth_maps, and of `hierarchy`, its min/max depth
// hierarchy), whose source is view.source_width wide: a square in the
// view's x-y plane at its eye (spot), a disc there (`disc`: a point
// light's sphere), or a disc of directions (orthographic: the sun).
// `pixel` seeds the shift of the source's grid of points. `max_cells`:
// the settings' backprojection_cells, patches per side of the region at
// most.
float shadow_backprojection(sampler2DArray depth_maps, sampler2DArray hierarchy, int layer,
                            GpuShadowView view, ShadowLookup s, float z, vec2 gradient, vec3 normal,
                            vec3 shading_normal, bool disc, ivec2 pixel, int max_cells) {
  ivec2 size = textureSize(depth_maps, 0).xy;
  float texel = view.depth_range.z;
  bool sphere = disc && view.perspective != 0 && view.source_width > 0.0;
  disc = disc || view.perspective == 0;
  BackprojectionReceiver r = backprojection_receiver(view, s, z, gradient, normal,
                                                     shading_normal, sphere, size, pixel);
  float width = r.width;
  gradient = r.gradient;
  if (width <= 0.0) {  // a point source: the hard test
    return texelFetch(depth_maps, ivec3(ivec2(floor(r.center)), layer), 0).r < z ? 0.0 : 1.0;
  }

  // The cone from the receiver to the source is reach_per_k k texels wide
  // (half-width) at depth d (backprojection_k()). Cut at the near plane,
  // then twice at the nearest depth found in the last cut: no texel
  // outside a cut can hide any of the source (Guennebaud et al. 2007,
  // section 3.1). A cube face's distances are at least the axial depths,
  // by at most the factor of the cut's farthest corner: its nearest
  // distance z0 is an axial depth of z0 / sqrt(1 + 2 t^2) at the face's
  // corners (t: the face's half-width in tangent units), and taking z0
  // itself there cut away every blocker nearer than z0 along the axis (the
  // default scene's slab seen 35 degrees off a face's axis hid only 12 x 12
  // of the 16 x 16 points of a receiver in its umbra).
  float reach_per_k = 0.5 * width / texel;
  float near_depth = view.depth_range.x;
  if (view.radial_depth != 0) {
    float half_width = 0.5 * view.depth_range.w * texel;
    near_depth *= inversesqrt(1.0 + 2.0 * half_width * half_width);
  }
  float reach = reach_per_k * max(backprojection_k(view, near_depth, r.receiver), 0.0);
  ivec2 first, last;
  vec2 bounds = vec2(0.0);
  // A cube face's region reaches past its map into the other faces
  // (backprojection_outer_region()).
  bool cube = view.radial_depth != 0;
  int cube_first = cube ? backprojection_cube_first(view, layer) : 0;
  ivec2 outer_first = ivec2(0), outer_last = ivec2(-1);
  for (int cut = 0; cut < 2; ++cut) {
    backprojection_region(r.center, reach, size, first, last);
    bounds = backprojection_depth_bounds(hierarchy, layer, first, last);
    if (cube) {
      backprojection_outer_region(r.center, reach, size, outer_first, outer_last);
      vec2 outer = backprojection_cube_bounds(hierarchy, view, cube_first, outer_first,
                                              outer_last, size);
      bounds = vec2(min(bounds.x, outer.x), max(bounds.y, outer.y));
    }
    float nearest = linear_depth_of(view, min(bounds.x, z));
    if (cube) {
      vec2 corner = max(abs(backprojection_tan(view, vec2(min(first, outer_first)))),
                        abs(backprojection_tan(view, vec2(max(last, outer_last) + 1))));
      nearest *= inversesqrt(1.0 + dot(corner, corner));
    }
    reach = min(reach, reach_per_k * max(backprojection_k(view, nearest, r.receiver), 0.0));
  }
  backprojection_region(r.center, reach, size, first, last);
  bool outside = false;
  if (cube) {
    backprojection_outer_region(r.center, reach, size, outer_first, outer_last);
    outside = any(lessThan(outer_first, ivec2(0))) || any(greaterThanEqual(outer_last, size));
  }
  // The receiver's plane over the region lies within z -+ slope.
  float slope = (abs(gradient.x) + abs(gradient.y)) * (reach + 1.0);
  if (bounds.x >= z + slope) return 1.0;  // nothing in front of the receiver
  // Every texel of the cut in front: each ray to the source is behind the
  // map's surface where it crosses the farthest depth found.
  if (bounds.y < z - slope) return 0.0;

  uvec4 low = uvec4(0u), high = uvec4(0u);
  int span = max(last.x - first.x, last.y - first.y) + 1;
  // Then the second surfaces (view.second_layer: the nearest facing the
  // light behind the first ones, ShadowMapPass::execute()): a caster that
  // another hides from the source's centre (the default scene's sphere
  // under its slab) still hides parts of the source from a receiver that
  // sees it through the source's edges (Bavoil, Callahan and Silva,
  // "Robust Soft Shadow Mapping with Backprojection and Depth Peeling",
  // JGT 2008). They lie behind the first surfaces texel by texel, so
  // wherever the first are behind the receiver's plane, so are they.
  int surfaces = view.second_layer > 0 ? 2 : 1;
  r.steps_open =
      view.second_layer > 0 &&
      texelFetch(depth_maps, ivec3(ivec2(floor(r.center)), view.second_layer), 0).r >= z;
  SHADOW_FETCHED(int(view.second_layer > 0));
  if (span <= max_cells) {
    // The texels themselves, and the row and column below the region,
    // whose patches may reach into it.
    for (int surface = 0; surface < surfaces; ++surface) {
      int surface_layer = surface == 0 ? layer : view.second_layer;
      if (surface == 1 &&
          backprojection_depth_bounds(hierarchy, surface_layer, first, last).x >= z + slope) {
        break;  // the second surfaces all behind the receiver's plane
      }
      backprojection_texel_patches(depth_maps, surface_layer, view, r, max(first - 1, ivec2(0)),
                                   last, low, high);
    }
  } else {
    // The hierarchy's cells 2^level texels wide (level - 1 of it). A cell
    // whose depths all lie in front is a patch at its texels' mean depth;
    // a cell the receiver's plane cuts is read finer
    // (backprojection_cell_patch()).
    int level = min(findMSB((span - 1) / max_cells) + 1,
                    backprojection_levels(hierarchy));
    ivec2 cells = backprojection_cells(hierarchy, level - 1);
    ivec2 lo = min(max(first >> level, ivec2(1)) - 1, cells - 1);
    ivec2 hi = min(last >> level, cells - 1);
    // The least extent of the patches there and of their neighbours: at
    // the nearest depth over the cells and three beyond them (a merged
    // 2 x 2 reaches to the next one's).
    ivec2 n1 = min(((hi + 4) << level) - 1, size - 1);
    float nearest_extent = backprojection_least_extent(
        view, r, vec2(lo << level) - r.center, vec2(n1 + 1) - r.center,
        backprojection_depth_bounds(hierarchy, layer, lo << level, n1).x);
    // The 2 x 2 cells around the receiver are read finer: there a blocker
    // is nearest, its patch hides the most of the source, and a cell the
    // receiver's plane cuts (a contact: the box's foot) would hide all of
    // it from the receiver inside it (backprojection_near_patches()).
    // Default scene, 640x360, spot, RMSE at sources 0.5 / 1.5: 0.0056 /
    // 0.0138 with cells only, 0.0049 / 0.0116 so, 0.0045 / 0.0114 with
    // every cut cell's texels (at 1.5x the lighting pass's time; this:
    // 1.1x).
    ivec2 near_cells = backprojection_near_cells(r, level, cells);
    backprojection_near_patches(depth_maps, hierarchy, layer, view, r, level, nearest_extent, low,
                                high);
    // The cells two by two, from the hierarchy's next level (the last
    // one of a row or column takes an odd remainder): a 2 x 2 behind the
    // receiver's plane hides nothing; one wholly in front whose depths
    // project within BACKPROJECTION_FLAT of a source width of each other
    // is one patch (the inside of a blocker: its cells' patches would tile
    // the same rectangle) over the projections at both (at the nearest
    // alone its side away from the source's centre fell short of its
    // cells' by up to that much, a crack where their neighbours reach to
    // them: the default scene's spot at 1.5, 1280x720, RMSE 0.00320 ->
    // 0.00306); the others are read cell by cell.
    int levels = backprojection_levels(hierarchy);
    ivec2 parents = backprojection_cells(hierarchy, min(level, levels - 1));
    int merge_level = level < levels ? 1 : 0;  // 0: no coarser level, one cell each
    ivec2 plo = lo >> merge_level;
    ivec2 phi = merge_level == 1 ? min(hi >> 1, parents - 1) : hi;
    for (int py = plo.y; py <= phi.y; ++py) {
      for (int px = plo.x; px <= phi.x; ++px) {
        ivec2 p = ivec2(px, py);
        ivec2 c0 = max(p << merge_level, lo);
        ivec2 c1 = (p << merge_level) + merge_level;
        if (merge_level == 1) c1 = mix(c1, cells - 1, equal(p, parents - 1));
        c1 = min(c1, hi);
        vec2 a0 = vec2(c0 << level) - r.center;
        vec2 a1 = vec2(mix(ivec2(c1 + 1) << level, size, equal(c1, cells - 1))) - r.center;
        // The receiver's plane at the nearest of the cells' centres: a 2 x 2
        // whose nearest depth lies past it is left, though a cell of it may
        // lie before the plane at its own centre (backprojection_cell_patch()
        // would keep it). Taken at the farthest of the centres, no such cell
        // is lost, but the receiver's own surface is read cell by cell: the
        // default scene's spot at 1.5 (1280x720) 0.00320 -> 0.00318, the
        // lighting pass (640x360) 1145 -> 1756 ms.
        vec2 m0 = a0 + 0.5 * float(1 << level);
        vec2 m1 = max(a1 - 0.5 * float(1 << level), m0);
        float plane = z + dot(gradient, 0.5 * (m0 + m1)) - dot(abs(gradient), 0.5 * (m1 - m0));
        for (int surface = 0; surface < surfaces; ++surface) {
          int surface_layer = surface == 0 ? layer : view.second_layer;
          vec2 b = vec2(-1.0, 2.0);  // no coarser level: neither behind nor in front
          if (merge_level == 1) b = texelFetch(hierarchy, ivec3(p, surface_layer), level).rg;
          SHADOW_FETCHED(merge_level);
          // (The second surfaces lie behind the first.)
          if (b.x >= plane ||
              (merge_level == 1 &&
               backprojection_off_source(r, a0, a1,
                                         backprojection_least_extent(view, r, a0, a1, b.x),
                                         nearest_extent))) {
            break;
          }
          // The second surfaces near the receiver are mostly its own surface
          // seen past a caster (the ground under the sphere): read as cells.
          bool refine = surface == 0;
          bool near = refine && all(lessThanEqual(c0, near_cells + 1)) &&
                      all(greaterThanEqual(c1, near_cells));
          if (!near && b.y < plane) {
            vec2 mid = 0.5 * (a0 + a1);
            float extent = backprojection_extent(view, r, mid, b.x);
            float far_extent = backprojection_extent(view, r, mid, b.y);
            float reach = max(max(abs(a0.x), abs(a1.x)), max(abs(a0.y), abs(a1.y)));
            if (extent > 0.0 && far_extent > 0.0 &&
                reach * (far_extent - extent) <= BACKPROJECTION_FLAT) {
              if (!backprojection_above_plane(view, r, mid, b.x)) continue;
              float right = 0.0, up = 0.0;
              if (px + 1 < parents.x) {
                float depth = texelFetch(hierarchy, ivec3(px + 1, py, surface_layer), level).r;
                SHADOW_FETCHED(1);
                right = backprojection_reach(view, r, surface_layer, level + 1, b.x, depth,
                                             vec2(a1.x + 0.5 * (a1.x - a0.x), mid.y));
              }
              if (py + 1 < parents.y) {
                float depth = texelFetch(hierarchy, ivec3(px, py + 1, surface_layer), level).r;
                SHADOW_FETCHED(1);
                up = backprojection_reach(view, r, surface_layer, level + 1, b.x, depth,
                                          vec2(mid.x, a1.y + 0.5 * (a1.y - a0.y)));
              }
              backprojection_hide_span(r, a0, a1, extent, far_extent, right, up, low, high);
              continue;
            }
          }
          // One loop over the cells, not one per row and column: llvmpipe
          // ends every loop of a shader invocation after 65535 iterations
          // of them all, counted for the eight pixels it shades together.
          ivec2 n = c1 - c0 + 1;
          ivec2 c = ivec2(c0.x - 1, c0.y);
          for (int k = 0; k < n.x * n.y; ++k) {
            c = c.x < c1.x ? ivec2(c.x + 1, c.y) : ivec2(c0.x, c.y + 1);
            if (refine && all(greaterThanEqual(c, near_cells)) &&
                all(lessThanEqual(c, near_cells + 1))) {
              continue;  // read as texels above
            }
            backprojection_cell_patch(depth_maps, hierarchy, surface_layer, view, r, level, cells,
                                      c, nearest_extent, low, high);
          }
        }
      }
    }
  }

  if (outside) {
    // The region past a cube face's map, from the other faces
    // (backprojection_cube_cell()), in cells at most backprojection_cells
    // to its side: each a patch at its texels' mean depth (at their
    // nearest where the receiver's horizon cuts it; none wholly below),
    // reaching to no neighbour. One loop, the cells inside the map left.
    // scenes/point_seam.json under a point light 0.5 across (640x360,
    // 2048^2 maps), whose bar's penumbra crosses the edge between two
    // faces: RMSE 0.0119 -> 0.0068 (`hard --accumulate 256` at 4096^2:
    // 0.0051); at 1.5 across 0.0456 -> 0.0262 (0.0116). Reaching only to
    // the guard band, the band widened to its cap (N/8) read 0.0075 and
    // 0.0343, and every point light's texels were a third wider.
    int outer_span = max(outer_last.x - outer_first.x, outer_last.y - outer_first.y) + 1;
    int level = clamp(findMSB((outer_span - 1) / max_cells) + 1, 1,
                      backprojection_levels(hierarchy));
    int width = 1 << level;
    ivec2 c0 = outer_first >> level, c1 = outer_last >> level;
    ivec2 inner = (size - 1) >> level;
    ivec2 n = c1 - c0 + 1;
    for (int k = 0; k < n.x * n.y; ++k) {
      ivec2 c = c0 + ivec2(k % n.x, k / n.x);
      if (all(greaterThanEqual(c, ivec2(0))) && all(lessThanEqual(c, inner))) continue;
      vec2 a0 = vec2(c * width) - r.center, a1 = a0 + float(width);
      vec2 mid = 0.5 * (a0 + a1);
      vec3 m = backprojection_cube_cell(hierarchy, view, cube_first, r.center + mid, level - 1);
      if (!backprojection_above_plane(view, r, mid, m.x)) continue;
      float depth = backprojection_above_plane(view, r, mid, m.y) ? m.z : m.x;
      float extent = backprojection_depth_extent(
          view, r, backprojection_depth(view, depth, backprojection_tan(view, r.center + mid)));
      if (extent > 0.0) backprojection_hide_patch(r, a0, a1, extent, 0.0, 0.0, low, high);
    }
  }

  return backprojection_lit_fraction(view, r, low, high, disc);
}
