// Which texels of a shadow map hold surfaces that can block a receiver's
// light. A filter window around the receiver's lookup also covers texels
// of surfaces *beside* it: at the foot of a lit wall, the wall's texels
// are nearer the light than the ground's plane there, so a plain depth
// test counts them as occluders and darkens ground that sees the whole
// light. A surface blocks part of the light only if it lies inside the
// cone from the receiver to the light's source; texels outside that cone
// are not counted (they are the receiver's neighbours, not its blockers).
#pragma once
#include "penumbra.glsl"

// The world point a shadow view stores at map point uv with relative
// depth z_bar: on the light's ray through uv, where the view's depth
// (axial, or radial for point lights) is z_bar's. Both depths are affine
// along a ray through the eye, so one interpolation finds it.
vec3 shadow_map_point(GpuShadowView view, vec2 uv, float z_bar) {
  vec3 near_p, far_p;
  shadow_map_ray(view, uv, near_p, far_p);
  float d_near = light_linear_depth(view, near_p), d_far = light_linear_depth(view, far_p);
  return mix(near_p, far_p, (linear_depth_of(view, z_bar) - d_near) / (d_far - d_near));
}

// The cone from a receiver to the light's source.
struct OccluderCone {
  vec3 apex;             // the receiver (the lookup point)
  vec3 axis;             // unit direction towards the centre of the source
  float tan_half_angle;  // the source's angular radius, as a tangent
};

// The cone under which the receiver sees the light's source, widened to
// at least min_tan_half_angle: a spot light's square of width w as the
// disc through its corners (radius w / sqrt(2): an equal-area disc, w /
// sqrt(pi), left out the blockers that hide only a corner), a point
// light's sphere, the sun's disc of directions (GpuShadowView.source_width:
// 2 tan(radius)).
OccluderCone occluder_cone(GpuLight light, GpuShadowView view, vec3 receiver,
                           float min_tan_half_angle) {
  OccluderCone c;
  c.apex = receiver;
  c.axis = direction_to_light(light, receiver);
  float tan_half;
  if (int(light.position_type.w) == LIGHT_DIRECTIONAL) {
    tan_half = 0.5 * view.source_width;
  } else {
    float radius = view.source_width *
                   (int(light.position_type.w) == LIGHT_POINT ? 0.5 : 0.70710678);
    float distance = length(light.position_type.xyz - receiver);
    tan_half = radius / sqrt(max(distance * distance - radius * radius, 1e-12));
  }
  c.tan_half_angle = max(tan_half, min_tan_half_angle);
  return c;
}

// True if the surface at `occluder` lies inside the cone, within `slack`
// (world units: the footprint of the texel that stores it, so the texel
// on the receiver's own ray always counts).
bool inside_occluder_cone(OccluderCone c, vec3 occluder, float slack) {
  vec3 v = occluder - c.apex;
  float along = dot(v, c.axis);
  if (along <= 0.0) return false;  // not between the receiver and the light
  float across = length(v - along * c.axis);
  return across <= along * c.tan_half_angle + slack;
}

// Whether the surface stored in texel `texel` of view v (at relative depth
// `occluder_depth`) can block the cone's light.
bool texel_occludes(GpuShadowView view, ivec2 texel, ivec2 size, float occluder_depth,
                    OccluderCone cone) {
  vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  vec3 p = shadow_map_point(view, uv, occluder_depth);
  // Half a texel's diagonal at the occluder: the texel stands for all of it.
  float slack = 0.75 * shadow_texel_world(view, linear_depth_of(view, occluder_depth));
  return inside_occluder_cone(cone, p, slack);
}
