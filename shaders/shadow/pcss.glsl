// Percentage-closer soft shadows (Fernando 2005) over a depth-map array:
// the blocker search, the penumbra estimate from the blockers' mean depth,
// and PCF over it. Shared by penumbra's lighting pass and the lookup an
// engine includes (penumbra_shadows.glsl), so both shade alike.
#pragma once

#include "hard.glsl"
#include "pcf.glsl"

// The blocker search of PCSS over the depth map: the 2x2 texels around each
// of `samples` points of the pixel's rotated Poisson set (four depths a
// fetch), spread over a region `search` texels wide around map point
// `center` (texels; over the part of it `segment` keeps:
// disc_segment_point()), each tested against the receiver's
// plane at that texel. Only texels inside the cone from the receiver to
// the source count as blockers (occluder_cone.glsl). Returns (the
// blockers' count, their summed relative depth) and the same of those
// above the receiver's horizon (occluder_cone_above()). The hooks:
// depth_map_hooks.glsl.
#define SHADOW_BLOCKER_SEARCH_DEFINE(NAME, MAPS, TEXELS, GATHER)                               \
  vec4 NAME(MAPS depth_maps, int v, GpuShadowView view, vec2 center, float z, vec2 gradient,   \
            OccluderCone cone, vec2 rotation, float search, vec3 segment, int samples) {       \
    ivec2 size = TEXELS(depth_maps, v);                                                        \
    /* textureGather's order of the 2x2 texels, from the lower-left one. */                    \
    const ivec2 gathered[4] = ivec2[](ivec2(0, 1), ivec2(1, 1), ivec2(1, 0), ivec2(0));        \
    vec4 found = vec4(0.0);                                                                    \
    for (int k = 0; k < samples; ++k) {                                                        \
      vec2 sample_point =                                                                      \
          center + disc_segment_point(segment, rotated_poisson(k, rotation)) * (0.5 * search); \
      ivec2 lower_left = ivec2(floor(sample_point - 0.5));                                     \
      vec4 occluders = GATHER(depth_maps, v, lower_left);                                      \
      for (int c = 0; c < 4; ++c) {                                                            \
        /* Each texel against the receiver's plane at that texel. */                           \
        vec2 offset = vec2(lower_left + gathered[c]) + 0.5 - center;                           \
        ivec2 texel = clamp(lower_left + gathered[c], ivec2(0), size - 1);                     \
        if (occluders[c] < z + dot(gradient, offset)) {                                        \
          bvec2 counts = texel_occludes_above(view, texel, size, occluders[c], cone);          \
          if (counts.x) found.xy += vec2(1.0, occluders[c]);                                   \
          if (counts.y) found.zw += vec2(1.0, occluders[c]);                                   \
        }                                                                                      \
      }                                                                                        \
    }                                                                                          \
    return found;                                                                              \
  }
SHADOW_BLOCKER_SEARCH_DEFINE(shadow_blocker_search, sampler2DArray, shadow_map_texels,
                             shadow_map_gather)

// The blocker search over the region the light's source covers at the
// near plane (blocker_search_width()). `widen` scales the search region
// (and the caller's cone should follow).
vec4 cone_blocker_search(sampler2DArray depth_maps, int v, GpuShadowView view, ShadowLookup s,
                         float z, vec2 gradient, OccluderCone cone, vec2 rotation, int max_samples,
                         float widen) {
  float d_receiver = linear_depth_of(view, s.depth);
  float search = min(widen * blocker_search_width(view, d_receiver), float(MAX_PCF_WIDTH));
  return shadow_blocker_search(depth_maps, v, view, s.uv * vec2(textureSize(depth_maps, 0).xy), z,
                               gradient, cone, rotation, search, vec3(1.0, 0.0, -1.0),
                               pcss_search_sample_count(search, max_samples));
}

// The blockers (count, summed depth) of a receiver whose cone is `cone`
// (with its horizon: occluder_cone_above()), from what the search over
// the whole source found (`found`: cone_blocker_search()). Where the
// source lies wholly above the horizon, every blocker found. Where the
// horizon cuts it, those above the horizon: the part of the source below
// it does not count, and there the map shows the receiver's own body,
// which hides none of the part above (a box's face 3 degrees past grazing
// under an 8.45-degree sun, all of whose blockers were the box, read 0.16
// lit on average where the traced reference reads it wholly lit:
// HorizonBlockers in tests/gpu/horizon_blockers_test.cpp). If the search
// found blockers but none above the horizon, its few samples may have
// missed the sliver of the cone that counts: it searches again where the
// rays to the part of the source above the horizon cross the blockers'
// mean depth, the cone's segment there (the bunny under a spot light 0.5
// across: PCSS's RMSE 0.0139 with the first search's alone, 0.0122 so).
// That region is not capped at MAX_PCF_WIDTH, as the segment starts a
// fraction of the cone's own width from its axis: the face under a slab
// read 0.37 lit (the reference: 0) with the cap.
#define BLOCKERS_ABOVE_HORIZON_DEFINE(NAME, MAPS, SEARCH)                                       \
  vec2 NAME(MAPS depth_maps, int v, GpuShadowView view, vec2 center, float d_receiver, float z, \
            vec2 gradient, OccluderCone cone, vec2 rotation, vec4 found, int max_samples) {     \
    if (cone.segment.z <= -1.0 || found.x == 0.0) return found.xy;                             \
    if (found.z > 0.0) return found.zw;                                                        \
    float d_blocker = linear_depth_of(view, found.y / found.x);                                \
    float search = cone_width_at(view, d_receiver, d_blocker);                                 \
    return SEARCH(depth_maps, v, view, center, z, gradient, cone, rotation, search,            \
                  cone.segment, pcss_search_sample_count(search, max_samples))                 \
        .zw;                                                                                   \
  }
BLOCKERS_ABOVE_HORIZON_DEFINE(shadow_blockers_above_horizon, sampler2DArray,
                              shadow_blocker_search)

// The same at lookup s of a depth-map array.
vec2 blockers_above_horizon(sampler2DArray depth_maps, int v, GpuShadowView view, ShadowLookup s,
                            float z, vec2 gradient, OccluderCone cone, vec2 rotation, vec4 found,
                            int max_samples) {
  return shadow_blockers_above_horizon(
      depth_maps, v, view, s.uv * vec2(textureSize(depth_maps, 0).xy),
      linear_depth_of(view, s.depth), z, gradient, cone, rotation, found, max_samples);
}

// PCSS: blocker search (cone_blocker_search()), penumbra estimate, PCF over
// it, each with as many samples as its region's size in texels asks for,
// up to blocker_samples and filter_samples. The search's region's shape
// matters less than its spread, and the rotation dithers where a
// penumbra's outer end stops finding blockers. The filter takes bilinear
// compares at the pixel's shifted R2 set over the axis-aligned square of
// the light's source (square_samples.glsl). The filter's taps are not
// tested against the cone: PCF over the estimated penumbra stands for
// blockers at every depth, and those off the mean depth lie outside the
// receiver's cone at their own depth while still standing for the part of
// the source it hides. Testing each gathered texel against the cone
// (480x270, 2048^2 maps, against the traced reference) leaked light: RMSE
// 0.0172 -> 0.0220 on the default scene at source 0.5, 0.0128 -> 0.0281
// under a 3-degree sun, 0.0119 -> 0.0196 under a point light, better only
// at source 1.5 (0.0390 -> 0.0274). Both patterns come from one
// per-pixel noise value in [0, 1) (`rotation` is the angle 2 pi noise),
// so neighbouring pixels sample differently and a 3x3 neighbourhood
// averages much of the noise away. `cone`: the cone the light's source
// really subtends (occluder_cone() with no minimum).
float shadow_pcss(sampler2DArray depth_maps, sampler2DArrayShadow compare_maps, int v,
                  GpuShadowView view, ShadowLookup s, float z, vec2 gradient, OccluderCone cone,
                  vec2 rotation, float noise, int blocker_samples, int filter_samples) {
  float d_receiver = linear_depth_of(view, s.depth);
  vec4 searched =
      cone_blocker_search(depth_maps, v, view, s, z, gradient, cone, rotation, blocker_samples, 1.0);
  vec2 found = blockers_above_horizon(depth_maps, v, view, s, z, gradient, cone, rotation, searched,
                                      blocker_samples);
  float blockers = found.x, blocker_depth = found.y;
  if (blockers == 0.0) return 1.0;  // nothing between the receiver and the light
  float d_blocker = linear_depth_of(view, blocker_depth / blockers);
  float width = min(
      penumbra_world_width(view, d_receiver, d_blocker) / shadow_texel_world(view, d_receiver),
      float(MAX_PCF_WIDTH));
  if (width <= 0.0) return shadow_hard(depth_maps, v, s.uv, z, 0.0);
  float kernel = pcss_kernel_width(width);
  vec2 shift = square_sample_shift(noise);
  return shadow_pcf_bilinear(compare_maps, v, s.uv, z, gradient, kernel,
                             pcss_filter_sample_count(kernel, filter_samples), shift);
}
