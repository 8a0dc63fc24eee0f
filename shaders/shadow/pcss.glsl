// Percentage-closer soft shadows (Fernando 2005) over a depth-map array:
// the blocker search, the penumbra estimate from the blockers' mean depth,
// and PCF over it. Shared by penumbra's lighting pass and the lookup an
// engine includes (penumbra_shadows.glsl), so both shade alike.
#pragma once

#include "fetch_count.glsl"
#include "hard.glsl"
#include "pcf.glsl"

// The blocker search of PCSS over the depth map: the 2x2 texels around each
// of `samples` points of the pixel's rotated Poisson set (four depths a
// fetch), spread over a region `search` texels wide around map point
// `center` (texels), each tested against the receiver's plane at that
// texel. Only texels inside the cone from the receiver to the source count
// as blockers (occluder_cone.glsl); with `above`, only those above the
// receiver's horizon, the points spread over the cone's segment above it
// (occluder_cone_above(), disc_segment_point()). Returns (the blockers'
// count, their summed relative depth). The hooks: depth_map_hooks.glsl.
#define SHADOW_BLOCKER_SEARCH_DEFINE(NAME, MAPS, TEXELS, GATHER)                               \
  vec2 NAME(MAPS depth_maps, int v, GpuShadowView view, vec2 center, float z, vec2 gradient,   \
            OccluderCone cone, vec2 rotation, float search, bool above, int samples) {         \
    ivec2 size = TEXELS(depth_maps, v);                                                        \
    /* textureGather's order of the 2x2 texels, from the lower-left one. */                    \
    const ivec2 gathered[4] = ivec2[](ivec2(0, 1), ivec2(1, 1), ivec2(1, 0), ivec2(0));        \
    float blockers = 0.0, blocker_depth = 0.0;                                                 \
    for (int k = 0; k < samples; ++k) {                                                        \
      vec2 point = rotated_poisson(k, rotation);                                               \
      if (above) point = disc_segment_point(cone.segment, point);                              \
      vec2 sample_point = center + point * (0.5 * search);                                     \
      ivec2 lower_left = ivec2(floor(sample_point - 0.5));                                     \
      vec4 occluders = GATHER(depth_maps, v, lower_left);                                      \
      for (int c = 0; c < 4; ++c) {                                                            \
        /* Each texel against the receiver's plane at that texel. */                           \
        vec2 offset = vec2(lower_left + gathered[c]) + 0.5 - center;                           \
        ivec2 texel = clamp(lower_left + gathered[c], ivec2(0), size - 1);                     \
        if (occluders[c] < z + dot(gradient, offset) &&                                        \
            texel_occludes(view, texel, size, occluders[c], cone, above)) {                    \
          blockers += 1.0;                                                                     \
          blocker_depth += occluders[c];                                                       \
        }                                                                                      \
      }                                                                                        \
    }                                                                                          \
    return vec2(blockers, blocker_depth);                                                      \
  }
SHADOW_BLOCKER_SEARCH_DEFINE(shadow_blocker_search, sampler2DArray, shadow_map_texels,
                             shadow_map_gather)

// The blockers (count, summed depth) of a receiver whose cone is `cone`
// (with its horizon: occluder_cone_above()) in a region `search` texels
// wide around map point `center`. Where the source lies wholly above the
// horizon, every blocker the search finds. Where the horizon cuts it and
// the search found blockers, those above the horizon where the rays to
// the part of the source above it cross the blockers' mean depth: the
// cone's segment there, searched again. The part of the source below the
// horizon does not count, and there the map shows the receiver's own
// body, which hides none of the part above (a box's face 3 degrees past
// grazing under an 8.45-degree sun, all of whose blockers were the box,
// read 0.16 lit on average where the traced reference reads it wholly
// lit: HorizonBlockers in tests/gpu/horizon_blockers_test.cpp). Testing
// the horizon in the first search instead, whose few samples spread over
// the whole source miss the sliver that counts, read the bunny under a
// spot light 0.5 across at RMSE 0.0139 (0.0122 so), and took the lighting
// pass 148 ms where this takes 136 (llvmpipe, pcss, spot 1.5, 640x360;
// 125 with the cone alone), though 94 of its 141,000 pixels search twice.
// The second region is not capped at MAX_PCF_WIDTH, as the segment starts
// a fraction of the cone's own width from its axis: the face under a slab
// read 0.37 lit (the reference: 0) with the cap.
#define HORIZON_BLOCKER_SEARCH_DEFINE(NAME, MAPS, SEARCH)                                        \
  vec2 NAME(MAPS depth_maps, int v, GpuShadowView view, vec2 center, float d_receiver, float z, \
            vec2 gradient, OccluderCone cone, vec2 rotation, float search, int max_samples) {   \
    vec2 found = SEARCH(depth_maps, v, view, center, z, gradient, cone, rotation, search,      \
                        false, pcss_search_sample_count(search, max_samples));                 \
    if (cone.segment.z <= -1.0 || found.x == 0.0) return found;                                \
    search = cone_width_at(view, d_receiver, linear_depth_of(view, found.y / found.x));        \
    return SEARCH(depth_maps, v, view, center, z, gradient, cone, rotation, search, true,      \
                  pcss_search_sample_count(search, max_samples));                              \
  }
HORIZON_BLOCKER_SEARCH_DEFINE(shadow_horizon_blocker_search, sampler2DArray,
                              shadow_blocker_search)

// The blocker search over the region the light's source covers at the
// near plane (blocker_search_width()), with the cone's horizon
// (shadow_horizon_blocker_search()). `widen` scales the search region
// (and the caller's cone should follow).
vec2 cone_blocker_search(sampler2DArray depth_maps, int v, GpuShadowView view, ShadowLookup s,
                         float z, vec2 gradient, OccluderCone cone, vec2 rotation, int max_samples,
                         float widen) {
  float d_receiver = linear_depth_of(view, s.depth);
  float search = min(widen * blocker_search_width(view, d_receiver), float(MAX_PCF_WIDTH));
  return shadow_horizon_blocker_search(depth_maps, v, view,
                                       s.uv * vec2(textureSize(depth_maps, 0).xy), d_receiver, z,
                                       gradient, cone, rotation, search, max_samples);
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
  vec2 found =
      cone_blocker_search(depth_maps, v, view, s, z, gradient, cone, rotation, blocker_samples, 1.0);
  float blockers = found.x, blocker_depth = found.y;
  if (blockers == 0.0) return 1.0;  // nothing between the receiver and the light
  float d_blocker = linear_depth_of(view, blocker_depth / blockers);
  float width = min(
      penumbra_world_width(view, d_receiver, d_blocker) / shadow_texel_world(view, d_receiver),
      float(MAX_PCF_WIDTH));
  if (width <= 0.0) {
    SHADOW_FETCHED(1);
    return shadow_hard(depth_maps, v, s.uv, z, 0.0);
  }
  float kernel = pcss_kernel_width(width);
  vec2 shift = square_sample_shift(noise);
  return shadow_pcf_bilinear(compare_maps, v, s.uv, z, gradient, kernel,
                             pcss_filter_sample_count(kernel, filter_samples), shift);
}
