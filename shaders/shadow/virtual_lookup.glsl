// The lights' virtual shadow maps (docs/rendering.md, "Virtual shadow
// maps"; src/shadow/virtual_clipmap.hpp holds the CPU twins): which level
// (a directional light's clipmap level, a spot light's mip level) a point
// reads, and where its pages sit in the page table. Levels are numbered
// across the lights (virtual_shadow.lights[i]: light i's first and count).
// Shared by the marking pass, the page rendering and the lookup, so that
// they agree on every page.
#pragma once
#include "lookup.glsl"
#include "penumbra.glsl"

layout(std140, binding = BINDING_VIRTUAL_UBO) uniform VirtualShadowBlock {
  GpuVirtualShadow virtual_shadow;
};

const int VIRTUAL_TEXELS = VIRTUAL_PAGES * VIRTUAL_PAGE_TEXELS;

// Texels along a side of level `level`: 16,384, or a spot's mip level's.
int virtual_level_texels(int level) {
  return int(virtual_shadow.levels[level].depth_range.w);
}

// Light i's finest level whose texel at `world` is no larger than the
// pixel's footprint there (its camera distance times the footprint per
// unit distance): at least one texel per pixel. virtual_level_of() is the
// CPU twin.
int virtual_level(int i, vec3 world) {
  ivec4 light = virtual_shadow.lights[i];
  GpuShadowView first = virtual_shadow.levels[light.x];
  float footprint = length(world - virtual_shadow.camera.xyz) * virtual_shadow.camera.w;
  float texel = shadow_texel_world(first, light_linear_depth(first, world));
  float l = floor(log2(max(footprint, 1e-30) / max(texel, 1e-30)));
  return light.x + int(clamp(l, 0.0, float(light.y - 1)));
}

// The page-table slot of a world page: the table is addressed modulo 128
// in the world's page grid (two's complement: -1 & 127 = 127, the floored
// modulo).
ivec2 virtual_page_slot(ivec2 world_page) {
  return world_page & (VIRTUAL_PAGES - 1);
}

// The slot of page `page` (0..127 from the level's first) of level `level`
// (a spot level's origin is (0, 0): its slot is the page).
ivec2 virtual_level_slot(int level, ivec2 page) {
  return virtual_page_slot(virtual_shadow.origins[level].xy + page);
}

// The last of light i's levels.
int virtual_last_level(int i) {
  return virtual_shadow.lights[i].x + virtual_shadow.lights[i].y - 1;
}

// The level a window `world_width` wide at `world` around a lookup of
// light i's level `level` reads: the first at or above `level` (coarser)
// where it spans at most `window` texels.
int virtual_window_level(int i, int level, vec3 world, float world_width, float window) {
  int l = level;
  while (l < virtual_last_level(i)) {
    GpuShadowView view = virtual_shadow.levels[l];
    if (world_width <= window * shadow_texel_world(view, light_linear_depth(view, world))) break;
    ++l;
  }
  return l;
}

// The region where the source's blockers can lie around a receiver at
// `world` (PCSS's blocker search, backprojection's cone cut at the nearest
// caster), in texels of level `at` when the receiver reads level `level`:
// blocker_search_width() from the receiver's level's nearest depth (its
// column holds every caster that can shadow it), scaled by the ratio of
// the two levels' texels. One region in world units for every level it is
// read from, so the blockers found do not change where that level does.
float virtual_search_texels(int level, int at, vec3 world) {
  GpuShadowView view = virtual_shadow.levels[level];
  return blocker_search_width(view, light_linear_depth(view, world)) * view.depth_range.z /
         virtual_shadow.levels[at].depth_range.z;
}
// The level the region is read from: the first at or above `level` where
// it spans at most `window` texels.
int virtual_search_level(int i, int level, vec3 world, float window) {
  int l = level;
  while (l < virtual_last_level(i) && virtual_search_texels(level, l, world) > window) ++l;
  return l;
}
