// Dithered hard shadows for --accumulate N (src/render/accumulation.hpp).
// Sub-frame k renders a spot light's map from point k of its square, one
// point per stratum of width 1/sqrt(N) of the square; averaged, the N hard
// shadows would show N stepped copies of each wide penumbra's edge. So
// each pixel tests the ray to its own random point instead, the
// sub-frame's point moved by up to half a stratum (reflected back into
// the square at its edges), a different one every sub-frame: jittered
// rather than fixed strata, whose average is fine noise, not steps. (One
// offset per pixel for all sub-frames, a Cranley-Patterson rotation,
// measured noisier on the default scene.)
//
// The map was rendered from the sub-frame's point; the ray from the
// receiver to the point moved by delta (in the map's x and y) crosses
// linear depth z at the receiver's map position shifted by
// delta (1/z - 1/z_r) / (texel size at unit depth) texels (similar
// triangles). The ray is marched through the map from the receiver to the
// view's near plane, and is blocked where it crosses the depth of a
// surface the map holds there, in front of the receiver's own plane (as
// PCF compares with the receiver plane, so a sloped receiver does not
// shadow itself).
#pragma once

// A hash (pcg3d; Jarzynski & Olano, "Hash Functions for GPU Rendering",
// JCGT 2020) of the pixel and a seed as three values in [0, 1).
vec3 accumulate_hash(ivec2 pixel, int frame) {
  uvec3 v = uvec3(uvec2(pixel), uint(frame));
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return vec3(v >> 8u) * (1.0 / 16777216.0);
}

// The pixel's light offset in world units along the map's x and y: its
// point of the stratum (`cell` wide, a fraction of the square) minus the
// sub-frame's `point`.
vec2 accumulate_light_offset(GpuShadowView view, vec2 random, vec2 point, float cell) {
  vec2 moved = point + (random - 0.5) * cell;
  moved = 1.0 - abs(1.0 - abs(moved));  // reflected into [0, 1]: stays uniform
  return (moved - point) * view.source_width;
}

// Fraction of light (0 or 1) along the ray to the light moved by
// `light_offset` (world units, perspective views only). `z` is the
// receiver's biased z-bar, `gradient` its plane's z-bar change per texel,
// `jitter` in [0, 1) places the march's steps.
float shadow_hard_dithered(sampler2DArray depth_maps, int layer, GpuShadowView view,
                           ShadowLookup s, float z, vec2 gradient, vec2 light_offset,
                           float jitter) {
  ivec2 size = textureSize(depth_maps, 0).xy;
  vec2 center = s.uv * vec2(size);
  // No early test of the receiver's own texel: the map says whether the
  // sub-frame's point sees the receiver, not whether the moved point does
  // (ending there would darken every penumbra: the dither could take light
  // away but never give it).
  float bias = s.depth - z;
  float z_receiver = linear_depth_of(view, s.depth);
  float t_max = max(1.0 / view.depth_range.x - 1.0 / z_receiver, 0.0);
  vec2 reach = light_offset * t_max / view.depth_range.z;  // texels, at the near plane
  int steps = clamp(int(ceil(0.5 * length(reach))), 1, 16);  // about one per 2 texels
  // Each step covers the ray from the previous point towards the light: it
  // is blocked where, at the step's texel, the map's surface lies in that
  // stretch of depth (the ray crosses it), in front of the receiver's
  // plane. The last step takes everything up to the near plane.
  float previous = s.depth;
  for (int j = 0; j < steps; ++j) {
    float f = (float(j) + jitter) / float(steps);  // (0, 1): receiver to near plane
    vec2 offset = reach * f;
    ivec2 texel = ivec2(floor(center + offset));
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) break;
    float ray = relative_depth_of(view, 1.0 / (t_max * f + 1.0 / z_receiver));
    float receiver = z + dot(gradient, offset);
    float occluder = texelFetch(depth_maps, ivec3(texel, layer), 0).r;
    bool crossed = j == steps - 1 || occluder >= ray - bias;
    if (occluder < min(previous - bias, receiver) && crossed) return 0.0;
    previous = ray;
  }
  return 1.0;
}
