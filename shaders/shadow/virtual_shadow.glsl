// hard and pcf read through a light's virtual shadow maps:
// every texel fetch finds its page in the page table, so a window across
// a page border reads both pages, with no seam. Needs lookup.glsl,
// occluder_cone.glsl and poisson.glsl, and the shadow parameters.
#pragma once
#include "virtual_lookup.glsl"

// One layer per level of 128 x 128 entries (PAGE_* flags, pool page); a
// spot's mip level m uses its first (128 / 2^m)^2.
layout(binding = UNIT_VIRTUAL_PAGE_TABLE) uniform usampler2DArray virtual_page_table;
// The physical pages: z-bar of their level, one 128^2 layer each.
layout(binding = UNIT_VIRTUAL_POOL) uniform sampler2DArray virtual_pool;

uint virtual_page_entry(int level, ivec2 page) {
  return texelFetch(virtual_page_table, ivec3(virtual_level_slot(level, page), level), 0).r;
}

// z-bar at virtual texel `texel` of level `level` (clamped to the level),
// or -1 where its page is not resident.
float virtual_texel_depth(int level, ivec2 texel) {
  texel = clamp(texel, ivec2(0), ivec2(virtual_level_texels(level) - 1));
  uint entry = virtual_page_entry(level, texel / VIRTUAL_PAGE_TEXELS);
  if ((entry & PAGE_RESIDENT) == 0u) return -1.0;
  return texelFetch(virtual_pool,
                    ivec3(texel & (VIRTUAL_PAGE_TEXELS - 1), int(entry & PAGE_INDEX_MASK)), 0)
      .r;
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

// The level light i's lookup at `world` reads: virtual_level(), or where
// its page is missing (the pool ran out; or the point lies within a
// rounding error of a level's boundary and its neighbours marked the
// other level), the nearest coarser level holding it, then the nearest
// finer; -1 if none.
int virtual_resident_level(int i, vec3 world) {
  int level = virtual_level(i, world);
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

// The texel light i's virtual map's lookup reads at `world`
// (texel_density.glsl's shading_texel() for a light with virtual maps):
// its resident level's.
ShadingTexel virtual_shading_texel(int i, vec3 world) {
  int level = virtual_resident_level(i, world);
  if (level < 0) return ShadingTexel(0.0, false);
  GpuShadowView view = virtual_shadow.levels[level];
  return ShadingTexel(shadow_texel_world(view, light_linear_depth(view, world)), true);
}

// The hard test at the texel under uv; a missing page is lit.
float virtual_hard(int level, vec2 uv, float depth) {
  vec2 texel = uv * float(virtual_level_texels(level));
  float occluder = virtual_texel_depth(level, ivec2(floor(texel)));
  return occluder < 0.0 || depth <= occluder ? 1.0 : 0.0;
}

// The hardware's 2x2 bilinear compare (pcf with one sample), fetched
// texel by texel through the page table: the four tests weighted as
// GL_LINEAR weighs them.
float virtual_bilinear_compare(int level, vec2 uv, float depth) {
  vec2 p = uv * float(virtual_level_texels(level)) - 0.5;
  ivec2 base = ivec2(floor(p));
  vec2 f = p - vec2(base);
  float lit[4];
  for (int c = 0; c < 4; ++c) {
    float occluder = virtual_texel_depth(level, base + ivec2(c & 1, c >> 1));
    lit[c] = occluder < 0.0 || depth <= occluder ? 1.0 : 0.0;
  }
  return mix(mix(lit[0], lit[1], f.x), mix(lit[2], lit[3], f.x), f.y);
}

// shadow_pcf() (pcf.glsl) over the level's virtual texels.
float virtual_pcf(int level, GpuShadowView view, OccluderCone cone, vec2 uv, float depth,
                  vec2 gradient, float width, int samples, vec2 rotation) {
  ivec2 size = ivec2(virtual_level_texels(level));
  vec2 center = uv * vec2(size);
  float lit = 0.0;
  for (int i = 0; i < samples; ++i) {
    vec2 offset = rotated_poisson(i, rotation) * (0.5 * width);  // texels
    ivec2 texel = clamp(ivec2(floor(center + offset)), ivec2(0), size - 1);
    float receiver = depth + dot(gradient, offset);
    float occluder = virtual_texel_depth(level, texel);
    bool blocked = occluder >= 0.0 && receiver > occluder &&
                   texel_occludes(view, texel, size, occluder, cone);
    lit += blocked ? 0.0 : 1.0;
  }
  return lit / float(samples);
}

// Fraction of light i's light reaching the point through its virtual
// maps, for SHADOW_TECHNIQUE hard or pcf.
float virtual_shadow_factor(int i, GpuShadow params, GpuLight light, vec3 world, vec3 normal,
                            vec2 rotation) {
  int level = virtual_resident_level(i, world);
  if (level < 0) return 1.0;
  GpuShadowView view = virtual_shadow.levels[level];
  ShadowLookup s = shadow_lookup(view, world, normal, params.normal_offset);
  if (!s.inside) return 1.0;
  float z = s.depth - shadow_bias(params, s, normal, direction_to_light(light, world), 0.0);
#if SHADOW_TECHNIQUE == TECHNIQUE_PCF
  if (params.pcf_width <= 0.0) return virtual_hard(level, s.uv, z);
  if (params.pcf_samples == 1) return virtual_bilinear_compare(level, s.uv, z);
  vec2 gradient = receiver_depth_gradient(view, s, normal, params.max_slope);
  OccluderCone cone = occluder_cone(light, view, s.position, PCF_MIN_CONE_TAN);
  return virtual_pcf(level, view, cone, s.uv, z, gradient, params.pcf_width, params.pcf_samples,
                     rotation);
#else
  return virtual_hard(level, s.uv, z);
#endif
}
