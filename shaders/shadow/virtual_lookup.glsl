// A directional light's virtual shadow maps (docs/rendering.md, "Virtual
// shadow maps"; src/shadow/virtual_clipmap.hpp holds the CPU twins): which
// clipmap level a point reads, and where its pages sit in the page table.
// Shared by the marking pass, the page rendering and the lookup, so that
// they agree on every page.
#pragma once

// The block's binding: penumbra's own, or the engine's in the lookup it
// includes (penumbra_shadows.glsl defines it from ShadowBindings).
#ifndef VIRTUAL_BLOCK_BINDING
#define VIRTUAL_BLOCK_BINDING BINDING_VIRTUAL_UBO
#endif
layout(std140, binding = VIRTUAL_BLOCK_BINDING) uniform VirtualShadowBlock {
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

// The clip position in world page `page` of a level seen through `view`
// of the point at light-view position `p` (view.view * world): the page's
// square in light space is world page * page size, a power of two times
// an integer, so every page meets its neighbours exactly; the depth is
// the level's z-bar, as a cascade's (caster_position.glsl): orthographic,
// so the rasterizer's depth is z-bar itself.
vec4 virtual_page_clip_position(GpuShadowView view, ivec2 page, vec3 p) {
  float page_size = view.depth_range.z * float(VIRTUAL_PAGE_TEXELS);
  vec2 local = (p.xy - vec2(page) * page_size) / page_size;
  float z_bar = (-p.z - view.depth_range.x) / (view.depth_range.y - view.depth_range.x);
  return vec4(local * 2.0 - 1.0, z_bar, 1.0);
}
