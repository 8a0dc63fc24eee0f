// Where a world-space point falls in a shadow view's map, and how much
// bias its depth comparison needs. A light's views (src/shadow/
// shadow_views.hpp) are layers of the shadow-map arrays; everything here
// works on one view.
#pragma once

struct ShadowLookup {
  vec3 position;  // the looked-up point: the surface point moved by the normal offset
  vec2 uv;        // shadow-map coordinates, in [0, 1] inside the map
  float depth;    // receiver's relative depth z-bar
  float texel;    // world size of one shadow-map texel at the receiver
  // The same size in z-bar units: converts the parameters given in texels
  // (biases, VSM's minimum variance) to this view's depth range, so they
  // mean the same at every scene scale.
  float texel_depth;
  bool inside;    // false outside the view's frustum: treated as lit
};

// The view's depth z of a view-space point: the distance along -z, or the
// distance from the eye for radial depth (point lights).
float view_space_depth(GpuShadowView view, vec3 view_position) {
  return view.radial_depth != 0 ? length(view_position) : -view_position.z;
}

float light_linear_depth(GpuShadowView view, vec3 world) {
  return view_space_depth(view, (view.view * vec4(world, 1.0)).xyz);
}

float relative_depth_of(GpuShadowView view, float z) {
  return (z - view.depth_range.x) / (view.depth_range.y - view.depth_range.x);
}

// World size of one texel where the point is: grows with depth for a
// perspective view (for radial depth the distance bounds the axial depth
// from above, so the size is not underestimated), constant for an
// orthographic one.
float shadow_texel_world(GpuShadowView view, float linear_depth) {
  return view.perspective != 0 ? view.depth_range.z * linear_depth : view.depth_range.z;
}

// Unit direction from the point towards the light.
vec3 direction_to_light(GpuLight light, vec3 world) {
  return int(light.position_type.w) == LIGHT_DIRECTIONAL ? -light.direction_cos_outer.xyz
                                                         : normalize(light.position_type.xyz - world);
}

// Projects the point after moving it `normal_offset` texels along its
// normal (normal-offset shadows: the shift scales with the texel size, so
// it does not depend on the map's resolution).
ShadowLookup shadow_lookup(GpuShadowView view, vec3 world, vec3 normal, float normal_offset) {
  float texel = shadow_texel_world(view, light_linear_depth(view, world));
  vec3 p = world + normal * (normal_offset * texel);
  vec4 clip = view.view_projection * vec4(p, 1.0);
  ShadowLookup s;
  s.position = p;
  s.uv = clip.xy / clip.w * 0.5 + 0.5;
  float z = light_linear_depth(view, p);
  s.depth = relative_depth_of(view, z);
  s.texel = shadow_texel_world(view, z);
  s.texel_depth = s.texel / (view.depth_range.y - view.depth_range.x);
  s.inside = clip.w > 0.0 && all(greaterThanEqual(s.uv, vec2(0.0))) &&
             all(lessThanEqual(s.uv, vec2(1.0)));
  return s;
}

// Constant plus slope-scaled bias, both in texels, returned in z-bar
// units. The slope term is the receiver's depth change across one texel,
// tan(theta) * texel, where theta is the angle between its normal and the
// direction to the light; tan is capped so that grazing surfaces do not
// push the bias to infinity. Texels, converted with the view's own depth
// range, keep the bias the same fraction of a texel whatever the scene's
// size (a bias in z-bar would shrink in world units as the range tightens).
// A filter of radius W texels spreads a planar receiver's own depth over
// +-W texels of that slope; the filtered techniques compare against the
// whole spread, so their slope term grows by filter_slope_bias per texel
// of radius (W = 0 for the techniques that test single texels).
// (A mipmapped lookup filters wider still: its radius is then a fraction.)
float shadow_bias(GpuShadow params, ShadowLookup s, vec3 normal, vec3 to_light,
                  float filter_radius) {
  float cos_theta = clamp(abs(dot(normal, to_light)), 1e-4, 1.0);
  float tan_theta = min(sqrt(1.0 - cos_theta * cos_theta) / cos_theta, params.max_slope);
  float slope_texels = params.slope_bias + params.filter_slope_bias * filter_radius;
  return (params.constant_bias + slope_texels * tan_theta) * s.texel_depth;
}

// Shadow-map coordinates of a world point in a view (the uv of shadow_lookup()).
vec2 shadow_map_uv(GpuShadowView view, vec3 world) {
  vec4 clip = view.view_projection * vec4(world, 1.0);
  return clip.xy / clip.w * 0.5 + 0.5;
}

// The world points where the light's ray through shadow-map point uv
// meets the view's near and far clip planes.
void shadow_map_ray(GpuShadowView view, vec2 uv, out vec3 near_point, out vec3 far_point) {
  vec4 near_h = view.inverse_view_projection * vec4(uv * 2.0 - 1.0, -1.0, 1.0);
  vec4 far_h = view.inverse_view_projection * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
  near_point = near_h.xyz / near_h.w;
  far_point = far_h.xyz / far_h.w;
}

// Relative depth at which the light's ray through shadow-map point uv meets
// the receiver's tangent plane (through `world`, normal `normal`). Tests
// over a filter window compare each texel with this depth rather than the
// centre's, so a sloped receiver does not shadow itself (receiver-plane
// depth, after Isidoro 2006, evaluated exactly by ray-plane intersection).
float receiver_plane_depth(GpuShadowView view, vec3 world, vec3 normal, vec2 uv, float fallback) {
  vec3 origin, far_point;
  shadow_map_ray(view, uv, origin, far_point);
  vec3 direction = far_point - origin;
  float denominator = dot(normal, direction);
  if (abs(denominator) < 1e-8) return fallback;  // ray along the plane
  float t = dot(normal, world - origin) / denominator;
  if (t <= 0.0) return fallback;
  return relative_depth_of(view, light_linear_depth(view, origin + t * direction));
}
