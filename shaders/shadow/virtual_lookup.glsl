// The lights' virtual shadow maps (docs/rendering.md, "Virtual shadow
// maps"; src/shadow/virtual_clipmap.hpp holds the CPU twins): which level
// (a directional light's clipmap level, a spot light's mip level) a point
// reads, and where its pages sit in the page table. Levels are numbered
// across the lights (virtual_shadow.lights[i]: light i's first and count).
// Shared by the marking pass, the page rendering and the lookup, so that
// they agree on every page.
#pragma once
#include "lookup.glsl"

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
