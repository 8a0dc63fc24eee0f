// Moment soft shadows from summed-area tables (--filter sat --soft): the
// penumbra-sized filter of the filterable techniques, with the depth maps'
// contact test. Shared by penumbra's lighting pass and the lookup an
// engine includes (penumbra_shadows.glsl).
#pragma once

#include "../filter/sat.glsl"
#include "filtered.glsl"
#include "pcss.glsl"

// Soft moment shadows test each texel of the depth map this close to the
// receiver (texels) for blockers inside the light's cone.
#define CONTACT_WINDOW_RADIUS 3

// The blocker search over filtered map values m for a receiver at relative
// depth z: (the blockers' mean relative depth, their fraction G).
// msm with --soft-two-moment-blockers takes VSM's estimate, which measured
// closer at the bunny's foot (RMSE 0.030 instead of 0.0325 with a 1.5-wide
// source) and farther off on the default scene (0.035 instead of 0.027).
vec2 filtered_blocker_search(int technique, bool quantized, GpuShadow params, vec4 m, float z,
                             float texel_depth) {
  if ((technique == TECHNIQUE_MSM || technique == TECHNIQUE_MSM16) &&
      params.two_moment_blockers == 0) {
    // Four moments: the mean of the quadrature's atoms in front of the
    // receiver (msm_blocker_search(), Peters et al. 2016).
    vec2 found = quantized ? msm_blocker_search(msm_dequantize(m), msm_signed_depth(z),
                                                params.msm_alpha, MSM_BIAS_16)
                           : msm_blocker_search(m, msm_signed_depth(z), params.msm_alpha,
                                                MSM_BIAS_32);
    return vec2(clamp(msm_unit_depth(found.x), 0.0, z), found.y);
  }
  // VSM's two moments (Yang et al., "Variance Soft Shadow Mapping", PG
  // 2010; ESM's one the same way):
  // the technique's own test gives the occluded fraction G, and with the
  // unoccluded part assumed at the receiver's depth z,
  // mean = G z_blocker + (1 - G) z, so z_blocker = (mean - (1 - G) z) / G.
  float occluded =
      1.0 - filtered_lit_fraction_of(technique, quantized, params, m, z, texel_depth);
  float z_blocker =
      (filtered_mean_depth_of(technique, quantized, params, m) - (1.0 - occluded) * z) /
      max(occluded, 1e-20);
  return vec2(clamp(z_blocker, 0.0, z), occluded);
}

// Soft shadows from the summed-area table (the moment counterpart of PCSS:
// Yang et al. 2010; Peters et al., "Moment Soft Shadow Mapping", I3D 2016).
// The moments over the blocker search region give the blockers' mean depth
// (filtered_blocker_search()); its penumbra sets the filter radius (at
// least the fixed --blur), read with a constant 2 x 16 fetches however
// wide it is; both squares sit at the lookup point's sub-texel position.
// Both test the receiver z biased for the fixed --blur radius: a bias that
// grows with the penumbra's kernel (as Peters et al. 2016 scale theirs, by
// filter_slope_bias per texel of radius here) measured worse against the
// traced reference (RMSE with a 1.5-wide source: msm 0.0272 instead of
// 0.0266 and vsm 0.058 instead of 0.054 on the default scene, msm 0.036
// instead of 0.033 on the bunny): it lifts the shadow off the ground at
// contacts, where the kernel is widest. `origin`: where the receiver's
// rays start; `shading_normal`: the horizon its blockers must lie above
// where it cuts the source (occluder_cone_above()).
float shadow_soft_moments(usampler2DArray sat, sampler2DArray depth_maps, int technique,
                         bool quantized, GpuShadow params, int v, GpuShadowView view,
                         ShadowLookup s, float z, GpuLight light, vec3 origin, vec3 normal,
                         vec3 shading_normal, vec2 rotation) {
  vec2 center = s.uv * vec2(textureSize(sat, 0).xy);
  float d_receiver = linear_depth_of(view, s.depth);
  float fixed_radius = float(params.blur_radius);
  float search_radius = min(max(0.5 * blocker_search_width(view, d_receiver), fixed_radius),
                            float(MAX_SOFT_RADIUS));
  vec2 found =
      filtered_blocker_search(technique, quantized, params,
                              sat_square_average(sat, v, center, search_radius, params.sat_scale),
                              z, s.texel_depth);
  if (found.y <= 0.0) return 1.0;  // no blockers: lit
  float penumbra = penumbra_world_width(view, d_receiver, linear_depth_of(view, found.x)) /
                   shadow_texel_world(view, d_receiver);
  float radius = min(max(0.5 * penumbra, fixed_radius), float(MAX_SOFT_RADIUS));
  // Blockers the moments cannot tell apart from a lit face's texels at the
  // receiver's foot (nearer the light than the receiver, but outside the
  // cone from it to the source), which darkened ground that sees the whole
  // light. The depth map can: the receiver is lit where neither PCSS's
  // cone-tested search over the source's region (circumscribing a spot
  // light's square: the disc of its area leaves out the corners) nor a
  // test of every texel next to the receiver (the sparse search misses
  // thin occluders: a pole) finds a surface inside the cone. Measured on
  // the default scene (msm, 480x270): the foot's darkening 0.205 -> 0 at a
  // 1.5-wide source, RMSE 0.0362 -> 0.0366 (0.5 wide: 0.0186 -> 0.0191),
  // the cost of the early outs the sparse search gets wrong. Where the
  // receiver's horizon cuts the source, only the surfaces above it count
  // (HORIZON_BLOCKER_SEARCH_DEFINE in pcss.glsl): the default scene's box
  // face past grazing under the 8.45-degree sun read dark (msm's RMSE
  // there 0.0740 -> 0.0259 at 1280x720).
  // Only where the penumbra widens the kernel past the fixed --blur: the
  // fixed filter is the anti-aliasing every receiver gets (with no source
  // size, --soft is exactly it).
  if (radius <= fixed_radius) {
    return filtered_lit_fraction_of(technique, quantized, params,
                                    sat_square_average(sat, v, center, radius, params.sat_scale),
                                    z, s.texel_depth);
  }
  OccluderCone cone = occluder_cone_above(light, view, s.position, origin, shading_normal);
  vec2 gradient =
      blocker_plane_gradient(receiver_depth_gradient(view, s, normal, params.max_slope), normal,
                             direction_to_light(light, origin));
  const float square_corners = 1.41421356;
  // occluder_cone() covers a square source's corners already.
  if (cone_blocker_search(depth_maps, v, view, s, z, gradient, cone, rotation,
                          params.pcss_blocker_samples, square_corners)
          .x == 0.0) {
    // Past a terminator only the texels above the horizon count.
    bool cut = cone.segment.z > -1.0;
    ivec2 size = textureSize(depth_maps, 0).xy;
    ivec2 middle = ivec2(floor(center));
    const int r = CONTACT_WINDOW_RADIUS;
    bool blocked = false;
    for (int y = -r; y <= r && !blocked; ++y) {
      for (int x = -r; x <= r && !blocked; ++x) {
        ivec2 texel = clamp(middle + ivec2(x, y), ivec2(0), size - 1);
        float occluder = texelFetch(depth_maps, ivec3(texel, v), 0).r;
        vec2 offset = vec2(texel) + 0.5 - center;
        blocked = occluder < z + dot(gradient, offset) &&
                  texel_occludes(view, texel, size, occluder, cone, cut);
      }
    }
    if (!blocked) return 1.0;
  }
  return filtered_lit_fraction_of(technique, quantized, params,
                                  sat_square_average(sat, v, center, radius, params.sat_scale), z,
                                  s.texel_depth);
}
