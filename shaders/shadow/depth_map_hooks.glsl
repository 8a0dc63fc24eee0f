// How the shared loops of the depth-map techniques (pcf.glsl, pcss.glsl,
// backprojection.glsl) read a depth map.
#pragma once

#include "fetch_count.glsl"

// The loops of the depth-map techniques are written once, over a depth
// map given by hooks, so that the cascades' texture arrays and a
// directional light's virtual maps (virtual_shadow.glsl, through the page
// table) share them. GLSL has no function parameters, so each loop is a
// macro that defines a function; its hooks are functions of (maps, layer):
//   TEXELS(maps, layer)          the map's size in texels (ivec2)
//   FETCH(maps, layer, texel)    z-bar at a texel inside the map (above 1:
//                                nothing there, as a missing page reads)
//   COMPARE(maps, layer, uv, z)  the 2x2 bilinear compare at uv
//   GATHER(maps, layer, texel)   the 2x2 depths from `texel` up and right,
//                                in textureGather's order: (0, 1), (1, 1),
//                                (1, 0), (0, 0)
// The cascades' hooks are the plain texture reads below, each one read
// (SHADOW_FETCHED(); the virtual maps' hooks count their page table's
// reads and their pool's).
ivec2 shadow_map_texels(sampler2DArray maps, int layer) {
  return textureSize(maps, 0).xy;
}
ivec2 shadow_map_texels(sampler2DArrayShadow maps, int layer) {
  return textureSize(maps, 0).xy;
}
float shadow_map_fetch(sampler2DArray maps, int layer, ivec2 texel) {
  SHADOW_FETCHED(1);
  return texelFetch(maps, ivec3(texel, layer), 0).r;
}
float shadow_map_compare(sampler2DArrayShadow maps, int layer, vec2 uv, float depth) {
  SHADOW_FETCHED(1);
  return texture(maps, vec4(uv, float(layer), depth));
}
// textureGather's four depths of the 2x2 texels from `lower_left` up.
vec4 shadow_map_gather(sampler2DArray maps, int layer, ivec2 lower_left) {
  SHADOW_FETCHED(1);
  return textureGather(maps, vec3(vec2(lower_left + 1) / vec2(textureSize(maps, 0).xy), layer));
}

