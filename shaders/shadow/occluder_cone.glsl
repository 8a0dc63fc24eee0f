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

// The cone from a receiver to the light's source, in the shadow view's
// own view space (the view matrix is a rigid lookAt, so lengths and angles
// are the world's), with what the per-texel test needs precomputed once
// per receiver: the homogeneous view-space point where the light's ray
// through map point ndc = uv * 2 - 1 meets the near plane is affine in ndc
// (ray_x * ndc.x + ray_y * ndc.y + ray_origin), so finding the point a
// texel stores costs a few multiplies instead of taking two clip points
// back through inverse_view_projection and view (four mat4 products).
struct OccluderCone {
  vec3 apex;             // the receiver (the lookup point), in view space
  vec3 axis;             // unit direction towards the centre of the source, in view space
  float tan_half_angle;  // the source's angular radius, as a tangent
  vec4 ray_x;            // the near-plane point's change per unit of ndc.x
  vec4 ray_y;            // ... of ndc.y
  vec4 ray_origin;       // ... at ndc (0, 0); orthographic views: divided through by w
};

// Columns x, y and (w - z) of view * inverse_view_projection: clip point
// (ndc, -1, 1) taken to view space.
void occluder_cone_rays(GpuShadowView view, inout OccluderCone c) {
  mat4 to_view = view.view * view.inverse_view_projection;
  c.ray_x = to_view[0];
  c.ray_y = to_view[1];
  c.ray_origin = to_view[3] - to_view[2];
  if (view.perspective == 0) {
    // Orthographic: w is the same for every ray (no perspective row).
    float inverse_w = 1.0 / c.ray_origin.w;
    c.ray_x *= inverse_w;
    c.ray_y *= inverse_w;
    c.ray_origin *= inverse_w;
  }
}

// The cone under which the receiver sees the light's source, widened to
// at least min_tan_half_angle: a spot light's square of width w as the
// disc through its corners (radius w / sqrt(2): an equal-area disc, w /
// sqrt(pi), left out the blockers that hide only a corner), a point
// light's sphere, the sun's disc of directions (GpuShadowView.source_width:
// 2 tan(radius)).
OccluderCone occluder_cone(GpuLight light, GpuShadowView view, vec3 receiver,
                           float min_tan_half_angle) {
  OccluderCone c;
  c.apex = (view.view * vec4(receiver, 1.0)).xyz;
  c.axis = mat3(view.view) * direction_to_light(light, receiver);
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
  occluder_cone_rays(view, c);
  return c;
}

// True if the view-space point `occluder` lies inside the cone, within
// `slack` (world units: the footprint of the texel that stores it, so the
// texel on the receiver's own ray always counts).
bool inside_occluder_cone(OccluderCone c, vec3 occluder, float slack) {
  vec3 v = occluder - c.apex;
  float along = dot(v, c.axis);
  if (along <= 0.0) return false;  // not between the receiver and the light
  float across = length(v - along * c.axis);
  return across <= along * c.tan_half_angle + slack;
}

// Whether the surface stored in texel `texel` of view v (at relative depth
// `occluder_depth`) can block the cone's light. The stored point lies on
// the texel's ray where the view's depth is the occluder's: d times the
// ray's direction scaled to unit depth along -z (perspective), or to unit
// length (radial depth); an orthographic ray keeps its x, y at z = -d.
bool texel_occludes(GpuShadowView view, ivec2 texel, ivec2 size, float occluder_depth,
                    OccluderCone cone) {
  vec2 ndc = (vec2(texel) + 0.5) / vec2(size) * 2.0 - 1.0;
  vec4 h = cone.ray_x * ndc.x + cone.ray_y * ndc.y + cone.ray_origin;
  float d = linear_depth_of(view, occluder_depth);
  vec3 p;
  if (view.perspective == 0) {
    p = vec3(h.xy, -d);
  } else {
    float scale = view.radial_depth != 0 ? inversesqrt(dot(h.xyz, h.xyz)) * sign(-h.z)
                                         : 1.0 / -h.z;
    p = h.xyz * (d * scale);
  }
  // Half a texel's diagonal at the occluder: the texel stands for all of it.
  float slack = 0.75 * shadow_texel_world(view, d);
  return inside_occluder_cone(cone, p, slack);
}
