// hard, pcf, pcss and backprojection read through a light's virtual
// shadow maps: every texel fetch finds its page in the page table,
// so a window across a page border reads both pages, with no seam. The
// loops are
// pcf.glsl's, pcss.glsl's and backprojection.glsl's, given the page
// table's hooks. Needs lookup.glsl, pcf.glsl, pcss.glsl and
// backprojection.glsl, and the shadow parameters.
#pragma once
#include "virtual_lookup.glsl"

// The units: penumbra's own, or the engine's in the lookup it includes
// (penumbra_shadows.glsl defines them from ShadowBindings).
#ifndef VIRTUAL_PAGE_TABLE_UNIT
#define VIRTUAL_PAGE_TABLE_UNIT UNIT_VIRTUAL_PAGE_TABLE
#endif
#ifndef VIRTUAL_POOL_UNIT
#define VIRTUAL_POOL_UNIT UNIT_VIRTUAL_POOL
#endif
// One layer per level of 128 x 128 entries (PAGE_* flags, pool page); a
// spot's mip level m uses its first (128 / 2^m)^2.
layout(binding = VIRTUAL_PAGE_TABLE_UNIT) uniform usampler2DArray virtual_page_table;
// The physical pages: z-bar of their level, one 128^2 layer each.
layout(binding = VIRTUAL_POOL_UNIT) uniform sampler2DArray virtual_pool;
#ifndef VIRTUAL_NO_DEPTH_BOUNDS
// Each physical page's nearest and farthest z-bar per cell of 16 x 16
// texels (virtual_bounds.comp): backprojection's cuts. The engine's
// lookup (hard and pcf only) has none.
layout(binding = UNIT_VIRTUAL_BOUNDS) uniform sampler2DArray virtual_bounds;
#endif

// What a texel of a missing page reads: beyond the level's far end, so it
// blocks nothing (the pool ran out; marking asks for every page a lookup
// reads).
const float VIRTUAL_MISSING_DEPTH = 2.0;

uint virtual_page_entry(int level, ivec2 page) {
  SHADOW_FETCHED(1);
  return texelFetch(virtual_page_table, ivec3(virtual_level_slot(level, page), level), 0).r;
}

// z-bar at virtual texel `texel` of level `level` (clamped to the level),
// or VIRTUAL_MISSING_DEPTH where its page is not resident.
float virtual_texel_depth(int level, ivec2 texel) {
  texel = clamp(texel, ivec2(0), ivec2(virtual_level_texels(level) - 1));
  uint entry = virtual_page_entry(level, texel / VIRTUAL_PAGE_TEXELS);
  if ((entry & PAGE_RESIDENT) == 0u) return VIRTUAL_MISSING_DEPTH;
  SHADOW_FETCHED(1);
  return texelFetch(virtual_pool,
                    ivec3(texel & (VIRTUAL_PAGE_TEXELS - 1), int(entry & PAGE_INDEX_MASK)), 0)
      .r;
}

// The page table's hooks for the shared loops (depth_map_hooks.glsl): the
// map is a level (`layer`); `pool` is virtual_pool, which
// virtual_texel_depth() reads.
ivec2 virtual_map_texels(sampler2DArray pool, int level) {
  return ivec2(virtual_level_texels(level));
}
float virtual_map_fetch(sampler2DArray pool, int level, ivec2 texel) {
  return virtual_texel_depth(level, texel);
}
// textureGather's order: (0, 1), (1, 1), (1, 0), (0, 0) from `lower_left`.
vec4 virtual_map_gather(sampler2DArray pool, int level, ivec2 lower_left) {
  return vec4(virtual_texel_depth(level, lower_left + ivec2(0, 1)),
              virtual_texel_depth(level, lower_left + ivec2(1, 1)),
              virtual_texel_depth(level, lower_left + ivec2(1, 0)),
              virtual_texel_depth(level, lower_left));
}
// The hardware's 2x2 bilinear compare, fetched texel by texel through the
// page table: the four tests weighted as GL_LINEAR weighs them.
float virtual_map_compare(sampler2DArray pool, int level, vec2 uv, float depth) {
  vec2 p = uv * float(virtual_level_texels(level)) - 0.5;
  ivec2 base = ivec2(floor(p));
  vec2 f = p - vec2(base);
  vec4 occluders = virtual_map_gather(pool, level, base);
  vec4 lit = vec4(lessThanEqual(vec4(depth), occluders));
  return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
}

SHADOW_PCF_DEFINE(virtual_pcf, sampler2DArray, virtual_map_texels, virtual_map_fetch)
SHADOW_PCF_BILINEAR_DEFINE(virtual_pcf_bilinear, sampler2DArray, virtual_map_texels,
                           virtual_map_compare)
SHADOW_BLOCKER_SEARCH_DEFINE(virtual_blocker_search, sampler2DArray, virtual_map_texels,
                             virtual_map_gather)
BACKPROJECTION_TEXEL_PATCHES_DEFINE(virtual_backprojection_patches, sampler2DArray,
                                    virtual_map_texels, virtual_map_gather)
HORIZON_BLOCKER_SEARCH_DEFINE(virtual_horizon_blocker_search, sampler2DArray,
                              virtual_blocker_search)

// The nearest and farthest z-bar over texels [first, last] of level
// `level` (a superset: the cells of 16 x 16 texels covering them); a
// missing page holds nothing.
vec2 virtual_depth_bounds(int level, ivec2 first, ivec2 last) {
#ifdef VIRTUAL_NO_DEPTH_BOUNDS
  // The engine's lookup keeps no bounds (its backprojection reads
  // cascades): nothing is cut.
  return vec2(0.0, VIRTUAL_MISSING_DEPTH);
#else
  const int cell = VIRTUAL_PAGE_TEXELS / VIRTUAL_BOUNDS_CELLS;
  ivec2 size = ivec2(virtual_level_texels(level));
  ivec2 lo = clamp(first, ivec2(0), size - 1) / cell;
  ivec2 hi = clamp(last, ivec2(0), size - 1) / cell;
  vec2 bounds = vec2(1.0e30, -1.0e30);
  for (int cy = lo.y; cy <= hi.y; ++cy) {
    for (int cx = lo.x; cx <= hi.x; ++cx) {
      ivec2 texel = ivec2(cx, cy) * cell;
      uint entry = virtual_page_entry(level, texel / VIRTUAL_PAGE_TEXELS);
      if ((entry & PAGE_RESIDENT) == 0u) {
        bounds.y = max(bounds.y, VIRTUAL_MISSING_DEPTH);
        continue;
      }
      SHADOW_FETCHED(1);
      vec2 m = texelFetch(virtual_bounds,
                          ivec3((texel & (VIRTUAL_PAGE_TEXELS - 1)) / cell,
                                int(entry & PAGE_INDEX_MASK)),
                          0)
                   .rg;
      bounds = vec2(min(bounds.x, m.x), max(bounds.y, m.y));
    }
  }
  return bounds;
#endif
}

// Whether the page of level `level` under `world` is resident.
bool virtual_page_resident(int level, vec3 world) {
  vec4 clip = virtual_shadow.levels[level].view_projection * vec4(world, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))))
    return false;
  ivec2 page = ivec2(floor(uv * float(virtual_level_texels(level) / VIRTUAL_PAGE_TEXELS)));
  return (virtual_page_entry(level, page) & PAGE_RESIDENT) != 0u;
}

// The level light i's lookup at `world` (on a receiver with unit normal
// `normal`) reads: virtual_level(), or where
// its page is missing (the pool ran out; or the point lies within a
// rounding error of a level's boundary and its neighbours marked the
// other level), the nearest coarser level holding it, then the nearest
// finer; -1 if none.
int virtual_resident_level(int i, vec3 world, vec3 normal) {
  int level = virtual_level(i, world, normal);
  if (virtual_page_resident(level, world)) return level;
  ivec4 light = virtual_shadow.lights[i];
  for (int l = level + 1; l < light.x + light.y; ++l) {
    if (virtual_page_resident(l, world)) return l;
  }
  for (int l = level - 1; l >= light.x; --l) {
    if (virtual_page_resident(l, world)) return l;
  }
  return -1;
}

#ifndef VIRTUAL_NO_TEXEL_DENSITY
// The texel light i's virtual map's lookup reads at `world`
// (texel_density.glsl's shading_texel() for a light with virtual maps):
// its resident level's.
ShadingTexel virtual_shading_texel(int i, vec3 world, vec3 normal) {
  int level = virtual_resident_level(i, world, normal);
  if (level < 0) return ShadingTexel(0.0, false);
  GpuShadowView view = virtual_shadow.levels[level];
  return ShadingTexel(shadow_texel_world(view, light_linear_depth(view, world)), true);
}
#endif

// The receiver as one level sees it: each level has its own texel and
// depth range, so the normal offset, the biased z-bar and the receiver's
// plane are the level's.
struct VirtualReceiver {
  int level;
  GpuShadowView view;
  ShadowLookup s;
  float z;  // biased z-bar
};

VirtualReceiver virtual_receiver(int level, GpuShadow params, GpuLight light, vec3 world,
                                 vec3 normal) {
  VirtualReceiver r;
  r.level = level;
  r.view = virtual_shadow.levels[level];
  r.s = shadow_lookup(r.view, world, normal, params.normal_offset);
  r.z = r.s.depth - shadow_bias(params, r.s, normal, direction_to_light(light, world), 0.0);
  return r;
}

// The hard test at the texel under the receiver's lookup.
float virtual_hard(VirtualReceiver r) {
  vec2 texel = r.s.uv * float(virtual_level_texels(r.level));
  float occluder = virtual_texel_depth(r.level, ivec2(floor(texel)));
  return r.z <= occluder ? 1.0 : 0.0;
}

// PCSS (pcss.glsl's shadow_pcss()) over light i's levels: the blocker
// search over the region the source covers from the receiver level's nearest
// caster, read at the level where it fits the window
// (virtual_search_level()); the penumbra's width in world units from the
// blockers' mean depth (Fernando 2005, eq. 1; a light's levels share its
// linear depths); the filter at the level where that width fits the
// window. A penumbra
// wider than a page is read from a coarser level rather than cut, and one
// that crosses a level border is filtered at the same level on both sides
// wherever it is wider than the finer level's window. The search and the
// filter take the receiver's plane as shadow_pcss() does, flat on a
// receiver facing away from the source's centre (blocker_plane_gradient();
// the filter took the triangle's plane there: RMSE at 1280x720, the bunny's
// sun at 11.86 degrees 0.03592 -> 0.03576, its spot at 1.5 0.01808 ->
// 0.01804, seven other cells within 0.00004).
float virtual_pcss(int i, VirtualReceiver r, GpuShadow params, GpuLight light, vec3 world,
                   vec3 normal, vec3 shading_normal, vec2 rotation, float noise) {
  const float window = float(VIRTUAL_PCSS_WINDOW);
  VirtualReceiver search = virtual_receiver(virtual_search_level(i, r.level, world, window), params,
                                            light, world, normal);
  float d_receiver = linear_depth_of(search.view, search.s.depth);
  float search_width =
      min(virtual_search_texels(r.level, search.level, world), float(MAX_PCF_WIDTH));
  vec3 to_light = direction_to_light(light, world);
  vec2 gradient = blocker_plane_gradient(
      receiver_depth_gradient(search.view, search.s, normal, params.max_slope), normal, to_light);
  OccluderCone cone =
      occluder_cone_above(light, search.view, search.s.position, world, shading_normal);
  vec2 center = search.s.uv * float(virtual_level_texels(search.level));
  vec2 found = virtual_horizon_blocker_search(virtual_pool, search.level, search.view, center,
                                              d_receiver, search.z, gradient, cone, rotation,
                                              search_width, params.pcss_blocker_samples);
  if (found.x == 0.0) return 1.0;  // nothing between the receiver and the light
  float d_blocker = linear_depth_of(search.view, found.y / found.x);
  float world_width = penumbra_world_width(search.view, d_receiver, d_blocker);
  if (world_width <= 0.0) return virtual_hard(r);
  VirtualReceiver f = virtual_receiver(virtual_window_level(i, r.level, world, world_width, window),
                                       params, light, world, normal);
  float width = min(world_width / shadow_texel_world(f.view, d_receiver), float(MAX_PCF_WIDTH));
  float kernel = pcss_kernel_width(width);
  return virtual_pcf_bilinear(virtual_pool, f.level, f.s.uv, f.z,
                              blocker_plane_gradient(
                                  receiver_depth_gradient(f.view, f.s, normal, params.max_slope),
                                  normal, to_light),
                              kernel, pcss_filter_sample_count(kernel, params.pcss_filter_samples),
                              square_sample_shift(noise));
}

// Backprojection (backprojection.glsl's shadow_backprojection()) over
// light i's levels: the cone from the receiver to the source (the sun's
// disc, a spot's square), cut at the receiver's level's
// nearest caster and then twice at the nearest depth the pages' cells find
// in it (virtual_depth_bounds()), is read at the level where it spans at
// most VIRTUAL_BACKPROJECTION_WINDOW texels, texel by texel: the coarser
// levels stand for the hierarchy's coarser cells (a level's texel
// holds the depth at its centre where a cell holds its nearest). If the
// cut region fits a finer level (at least the receiver's), it is read
// there, cut again from where the first level's cuts left it. `normal`
// is the triangle's, `shading_normal` the horizon the source is weighed
// against (docs/comparing.md, "The terminator model"). `pixel` seeds the
// shift of the source's grid.
float virtual_backprojection(int i, VirtualReceiver r0, GpuShadow params, GpuLight light,
                             vec3 world, vec3 normal, vec3 shading_normal, ivec2 pixel) {
  if (r0.view.source_width <= 0.0) return virtual_hard(r0);  // a point source
  const float window = float(VIRTUAL_BACKPROJECTION_WINDOW);
  int level = virtual_search_level(i, r0.level, world, window);
  // The first level's cut region's half-width, in units of the view's
  // depth_range.z (world units, or tangent units of a spot's map).
  float cut = -1.0;
  GpuShadow lookup_params =
      backprojection_bias_settings(params, normal, direction_to_light(light, world));
  for (int pass = 0; pass < 2; ++pass) {
    VirtualReceiver v = virtual_receiver(level, lookup_params, light, world, normal);
    GpuShadowView view = v.view;
    vec2 gradient = receiver_depth_gradient(view, v.s, normal, params.max_slope);
    ivec2 size = ivec2(virtual_level_texels(level));
    BackprojectionReceiver r =
        backprojection_receiver(view, v.s, v.z, gradient, normal, shading_normal, false, size,
                                pixel);
    // The cuts (shadow_backprojection()'s).
    float reach_per_k = 0.5 * view.source_width / view.depth_range.z;
    // At most the window (only the coarsest level can be asked for more:
    // blockers beyond it are missed there).
    float reach = min(cut >= 0.0 ? cut / view.depth_range.z
                                 : 0.5 * virtual_search_texels(r0.level, level, world),
                      0.5 * window);
    ivec2 first, last;
    vec2 bounds = vec2(0.0);
    for (int cut = 0; cut < 2; ++cut) {
      backprojection_region(r.center, reach, size, first, last);
      bounds = virtual_depth_bounds(level, first, last);
      float nearest = linear_depth_of(view, min(bounds.x, v.z));
      reach = min(reach, reach_per_k * max(backprojection_k(view, nearest, r.receiver), 0.0));
    }
    float texel_world = shadow_texel_world(view, light_linear_depth(view, world));
    int finer = virtual_window_level(i, r0.level, world, (2.0 * reach + 1.0) * texel_world, window);
    if (pass == 0 && finer < level) {
      level = finer;
      cut = reach * view.depth_range.z;
      continue;
    }
    backprojection_region(r.center, reach, size, first, last);
    // The receiver's plane over the region lies within z -+ slope.
    float slope = (abs(r.gradient.x) + abs(r.gradient.y)) * (reach + 1.0);
    if (bounds.x >= v.z + slope) return 1.0;  // nothing in front of the receiver
    if (bounds.y < v.z - slope) return 0.0;   // all of it in front: umbra
    uvec4 low = uvec4(0u), high = uvec4(0u);
    // The texels themselves, and the row and column below the region,
    // whose patches may reach into it.
    virtual_backprojection_patches(virtual_pool, level, view, r, max(first - 1, ivec2(0)), last,
                                   low, high);
    return backprojection_lit_fraction(view, r, low, high, view.perspective == 0);
  }
  return 1.0;
}

// PCF over the receiver's level of light i, for both entries below.
float virtual_pcf_factor(int i, VirtualReceiver r, GpuShadow params, GpuLight light, vec3 world,
                         vec3 normal, vec2 rotation) {
  if (params.pcf_width <= 0.0) return virtual_hard(r);
  if (params.pcf_samples == 1) return virtual_map_compare(virtual_pool, r.level, r.s.uv, r.z);
  vec2 gradient = receiver_depth_gradient(r.view, r.s, normal, params.max_slope);
  OccluderCone cone = occluder_cone(light, r.view, r.s.position, PCF_MIN_CONE_TAN);
  // The level's texel is the pixel's footprint (the one the level is
  // chosen by) rounded down to a power of two, bias / 2 levels finer still:
  // the window is pcf_width footprints wide over 2^(bias / 2) (1 to 2
  // texels each), so its world width follows the footprint and does not
  // double where the level changes (a step in the penumbra's width at each
  // level border).
  float footprint = virtual_footprint(i, world, normal) * exp2(-0.5 * virtual_shadow.params.z);
  float width = params.pcf_width * clamp(footprint / r.s.texel, 1.0, 2.0);
  return virtual_pcf(virtual_pool, r.level, r.view, cone, r.s.uv, r.z, gradient, width,
                     params.pcf_samples, rotation);
}

// Fraction of light i's light reaching the point through its virtual
// maps, for SHADOW_TECHNIQUE hard, pcf, pcss or backprojection.
// `normal` is the triangle's, `shading_normal` the horizon backprojection
// weighs the source against; `rotation` is the angle 2 pi noise, `noise`
// the pixel's noise value in [0, 1).
float virtual_shadow_factor(int i, GpuShadow params, GpuLight light, vec3 world, vec3 normal,
                            vec3 shading_normal, vec2 rotation, float noise) {
  int level = virtual_resident_level(i, world, normal);
  if (level < 0) return 1.0;
  VirtualReceiver r = virtual_receiver(level, params, light, world, normal);
  if (!r.s.inside) return 1.0;
#if SHADOW_TECHNIQUE == TECHNIQUE_PCF
  return virtual_pcf_factor(i, r, params, light, world, normal, rotation);
#elif SHADOW_TECHNIQUE == TECHNIQUE_PCSS
  return virtual_pcss(i, r, params, light, world, normal, shading_normal, rotation, noise);
#elif SHADOW_TECHNIQUE == TECHNIQUE_BACKPROJECTION
  return virtual_backprojection(i, r, params, light, world, normal, shading_normal,
                                ivec2(floor(gl_FragCoord.xy)));
#else
  return virtual_hard(r);
#endif
}

// The same for `technique` hard or pcf (TECHNIQUE_*) chosen at run time:
// the engine's lookup (penumbra_shadows.glsl).
float virtual_shadow_factor_of(int technique, int i, GpuShadow params, GpuLight light,
                               vec3 world, vec3 normal, vec2 rotation) {
  int level = virtual_resident_level(i, world, normal);
  if (level < 0) return 1.0;
  VirtualReceiver r = virtual_receiver(level, params, light, world, normal);
  if (!r.s.inside) return 1.0;
  if (technique == TECHNIQUE_PCF) {
    return virtual_pcf_factor(i, r, params, light, world, normal, rotation);
  }
  return virtual_hard(r);
}
