// Which texels of a shadow map hold surfaces that can block a receiver's
// light. A filter window around the receiver's lookup also covers texels
// of surfaces *beside* it: at the foot of a lit wall, the wall's texels
// are nearer the light than the ground's plane there, so a plain depth
// test counts them as occluders and darkens ground that sees the whole
// light. A surface blocks part of the light only if it lies inside the
// cone from the receiver to the light's source; texels outside that cone
// are not counted (they are the receiver's neighbours, not its blockers).
// Nor, for the techniques that model the source (PCSS, the moment soft
// shadows), are those below the receiver's horizon: they hide none of the
// part of the source that lights it (occluder_cone_above()).
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
  // The receiver's horizon (occluder_cone_above()): a blocker counts only
  // above the plane dot(horizon.xyz, p) + horizon.w = 0; (0, 0, 0, 1)
  // keeps every point.
  vec4 horizon;
  // The part of the source above that horizon as the cone's cross-section
  // shows it at every depth: the side axis . m >= cut of the unit disc
  // (axis: a direction in the map at the receiver); cut -1: the whole
  // disc.
  vec3 segment;  // (axis, cut)
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
  c.horizon = vec4(0.0, 0.0, 0.0, 1.0);
  c.segment = vec3(1.0, 0.0, -1.0);
  occluder_cone_rays(view, c);
  return c;
}

// The cone the light's source really subtends (occluder_cone() with no
// minimum) from `receiver` (world), for rays that start at `origin`
// (world) and count only above the horizon of `shading_normal`
// (docs/comparing.md, "The terminator model"): a surface below that plane
// hides none of the source points that count. Past a terminator (the source's centre below the
// horizon) the map shows the receiver's own body in front of it, below
// that plane (HORIZON_BLOCKER_SEARCH_DEFINE in pcss.glsl). The direction
// axis + t (t across the axis, within tan_half_angle of it) lies above the
// horizon where dot(n_across, t) > -n_axis: a segment of the cone's disc
// (OccluderCone::segment).
OccluderCone occluder_cone_above(GpuLight light, GpuShadowView view, vec3 receiver, vec3 origin,
                                 vec3 shading_normal) {
  OccluderCone c = occluder_cone(light, view, receiver, 0.0);
  vec3 n = normalize(mat3(view.view) * shading_normal);
  c.horizon = vec4(n, -dot(n, (view.view * vec4(origin, 1.0)).xyz));
  float n_axis = dot(n, c.axis);
  vec3 across = n - n_axis * c.axis;
  float cut = -n_axis / max(c.tan_half_angle * length(across), 1e-6);
  // The map's direction of `across` at the receiver: a perspective map
  // divides x and y by -z.
  vec2 along_map = view.perspective != 0 ? -c.apex.z * across.xy + c.apex.xy * across.z
                                         : across.xy;
  vec2 axis = length(along_map) > 0.0 ? normalize(along_map) : vec2(1.0, 0.0);
  c.segment = vec3(axis, clamp(cut, -1.0, 1.0));
  return c;
}

// The receiver's depth gradient per texel as the blocker tests take it: a
// receiver whose triangle faces away from the source's centre (past a
// terminator; `to_light`: towards the centre) is cut flat at its own depth,
// as backprojection cuts it (backprojection_receiver()). Its plane's near
// side is the receiver's own body there, and its horizon
// (occluder_cone_above()) keeps the blockers that count: the bunny under
// a point light 1.5 across, PCSS's RMSE 0.0202 with the plane, 0.0188
// flat (0.0192 before either).
vec2 blocker_plane_gradient(vec2 gradient, vec3 normal, vec3 to_light) {
  return dot(normal, to_light) > 0.0 ? gradient : vec2(0.0);
}

// Point p of the square [-1, 1]^2 taken into the segment (axis, cut) of the
// unit disc (OccluderCone::segment): along its axis [-1, 1] -> [cut, 1],
// across scaled by the chord's half-length there over the unit circle's
// at p, so a set spread over the disc stays spread over the segment.
vec2 disc_segment_point(vec3 segment, vec2 p) {
  float cut = segment.z;
  vec2 axis = segment.xy, side = vec2(-axis.y, axis.x);
  float u = dot(p, axis);
  float along = cut + (1.0 - cut) * 0.5 * (clamp(u, -1.0, 1.0) + 1.0);
  float chord = sqrt(max(1.0 - u * u, 0.0));
  float scale = chord > 0.0 ? sqrt(max(1.0 - along * along, 0.0)) / chord : 0.0;
  return along * axis + dot(p, side) * scale * side;
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

// The view-space point the surface stored in texel `texel` of view v (at
// the view's linear depth d) stands for: it lies on the texel's ray where
// the view's depth is d: d times the ray's direction scaled to unit depth
// along -z (perspective), or to unit length (radial depth); an
// orthographic ray keeps its x, y at z = -d.
vec3 texel_point(GpuShadowView view, ivec2 texel, ivec2 size, float d, OccluderCone cone) {
  vec2 ndc = (vec2(texel) + 0.5) / vec2(size) * 2.0 - 1.0;
  vec4 h = cone.ray_x * ndc.x + cone.ray_y * ndc.y + cone.ray_origin;
  if (view.perspective == 0) return vec3(h.xy, -d);
  float scale =
      view.radial_depth != 0 ? inversesqrt(dot(h.xyz, h.xyz)) * sign(-h.z) : 1.0 / -h.z;
  return h.xyz * (d * scale);
}

// Whether the surface stored in texel `texel` of view v (at relative depth
// `occluder_depth`) can block the cone's light, and with `above`, lies above
// the receiver's horizon as well (occluder_cone_above()).
bool texel_occludes(GpuShadowView view, ivec2 texel, ivec2 size, float occluder_depth,
                    OccluderCone cone, bool above) {
  float d = linear_depth_of(view, occluder_depth);
  vec3 p = texel_point(view, texel, size, d, cone);
  // Half a texel's diagonal at the occluder: the texel stands for all of it.
  return inside_occluder_cone(cone, p, 0.75 * shadow_texel_world(view, d)) &&
         (!above || dot(cone.horizon.xyz, p) + cone.horizon.w > 0.0);
}
