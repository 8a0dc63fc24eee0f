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

// The block's binding: penumbra's own, or the engine's in the lookup it
// includes (penumbra_shadows.glsl defines it from ShadowBindings).
#ifndef VIRTUAL_BLOCK_BINDING
#define VIRTUAL_BLOCK_BINDING BINDING_VIRTUAL_UBO
#endif
layout(std140, binding = VIRTUAL_BLOCK_BINDING) uniform VirtualShadowBlock {
  GpuVirtualShadow virtual_shadow;
};

const int VIRTUAL_TEXELS = VIRTUAL_PAGES * VIRTUAL_PAGE_TEXELS;

// Texels along a side of level `level`: 16,384, or a spot's mip level's.
int virtual_level_texels(int level) {
  return int(virtual_shadow.levels[level].depth_range.w);
}

// log2 of the largest texel that gives the pixel at `world`, on a
// receiver with unit normal `normal`, one texel (an area ratio, as
// texel_density.glsl measures it), over light i's first level's texel
// there. A pixel at distance d, off the view axis by theta, sees a solid
// angle a^2 cos^3(theta) (a: the footprint per unit distance on the axis);
// on a receiver whose normal makes cosines cos_v with the camera ray and
// cos_l with the light, it covers d^2 a^2 cos^3(theta) / cos_v, and a
// texel t covers t^2 / cos_l. One texel per pixel then needs
// t <= d a cos^1.5(theta) sqrt(cos_l / cos_v). The cosines' ratio only
// makes levels finer (a grazing view's footprint is long, not wide: a
// coarser texel would be wider than the pixel), by at most two levels (a
// receiver along the light's rays would need texels without end).
// virtual_footprint() is the pixel's side d a cos^1.5(theta) sqrt(cos_l /
// cos_v), in world units; virtual_level_coordinate() is the CPU twin
// (directional lights).
float virtual_footprint(int i, vec3 world, vec3 normal) {
  GpuShadowView first = virtual_shadow.levels[virtual_shadow.lights[i].x];
  vec3 ray = world - virtual_shadow.camera.xyz;
  float d = max(length(ray), 1e-30);
  ray /= d;
  float cos_axis = clamp(dot(ray, virtual_shadow.view_axis.xyz), 1e-3, 1.0);
  // Towards the light: a view's +z axis (the third row of its rotation),
  // or a spot's eye.
  mat3 rotation = mat3(first.view);
  vec3 to_light = first.perspective != 0
                      ? normalize(-(transpose(rotation) * first.view[3].xyz) - world)
                      : vec3(first.view[0][2], first.view[1][2], first.view[2][2]);
  float tilt = clamp(abs(dot(normal, to_light)) / max(abs(dot(normal, ray)), 1e-6), 1.0 / 16.0,
                     1.0);
  return d * virtual_shadow.camera.w * pow(cos_axis, 1.5) * sqrt(tilt);
}

float virtual_level_coordinate(int i, vec3 world, vec3 normal) {
  GpuShadowView first = virtual_shadow.levels[virtual_shadow.lights[i].x];
  float texel = shadow_texel_world(first, light_linear_depth(first, world));
  return log2(max(virtual_footprint(i, world, normal), 1e-30) / max(texel, 1e-30));
}

// Light i's level under level bias `bias` (half levels finer,
// PAGE_WANTED): the finest whose texel gives the pixel at least one
// texel, bias / 2 levels finer still. virtual_level_of() is the CPU twin.
int virtual_level_biased(int i, vec3 world, vec3 normal, int bias) {
  ivec4 light = virtual_shadow.lights[i];
  float l = floor(virtual_level_coordinate(i, world, normal) - 0.5 * float(bias));
  return light.x + int(clamp(l, 0.0, float(light.y - 1)));
}

// The level light i's lookup at `world` reads, under the bias the
// allocation chose.
int virtual_level(int i, vec3 world, vec3 normal) {
  return virtual_level_biased(i, world, normal, int(virtual_shadow.params.z));
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
