// A directional light's virtual shadow maps (docs/rendering.md, "Virtual
// shadow maps"; src/shadow/virtual_clipmap.hpp holds the CPU twins): which
// clipmap level a point reads, and where its pages sit in the page table.
// Shared by the marking pass, the page rendering and the lookup, so that
// they agree on every page.
#pragma once
#include "lookup.glsl"

layout(std140, binding = BINDING_VIRTUAL_UBO) uniform VirtualShadowBlock {
  GpuVirtualShadow virtual_shadow;
};

const int VIRTUAL_TEXELS = VIRTUAL_PAGES * VIRTUAL_PAGE_TEXELS;

// The finest level whose texel is no larger than the pixel's footprint at
// `world` (its camera distance times the footprint per unit distance): at
// least one texel per pixel. virtual_level_of() is the CPU twin.
int virtual_level(vec3 world) {
  float footprint = length(world - virtual_shadow.camera.xyz) * virtual_shadow.camera.w;
  float l = floor(log2(max(footprint, 1e-30) / virtual_shadow.params.x));
  return int(clamp(l, 0.0, float(virtual_shadow.counts.y - 1)));
}

// The page-table slot of a world page: the table is addressed modulo 128
// in the world's page grid (two's complement: -1 & 127 = 127, the floored
// modulo).
ivec2 virtual_page_slot(ivec2 world_page) {
  return world_page & (VIRTUAL_PAGES - 1);
}

// The slot of page `page` (0..127 from the level's first) of level `level`.
ivec2 virtual_level_slot(int level, ivec2 page) {
  return virtual_page_slot(virtual_shadow.origins[level].xy + page);
}

// The level a window `world_width` wide around a lookup of level `level`
// reads: the finest at or above `level` where it spans at most `window`
// texels (level l's texel is params.x 2^l).
int virtual_window_level(int level, float world_width, float window) {
  float l = ceil(log2(max(world_width / (window * virtual_shadow.params.x), 1e-30)));
  return clamp(max(int(l), level), 0, virtual_shadow.counts.y - 1);
}

// The region where the source's blockers can lie around a receiver at
// `world` (PCSS's blocker search, backprojection's cone cut at the
// nearest caster), in world units: the source's width over the depth from
// the level's nearest caster (blocker_search_width()). Each level has its
// own nearest depth, so the level the region is read from is the first at
// or above `level` where it spans at most `window` texels.
float virtual_search_world(int level, vec3 world) {
  GpuShadowView view = virtual_shadow.levels[level];
  return view.source_width * max(light_linear_depth(view, world) - view.depth_range.x, 0.0);
}
int virtual_search_level(int level, vec3 world, float window) {
  int l = level;
  while (l < virtual_shadow.counts.y - 1 &&
         virtual_search_world(l, world) > window * virtual_shadow.levels[l].depth_range.z) {
    ++l;
  }
  return l;
}
