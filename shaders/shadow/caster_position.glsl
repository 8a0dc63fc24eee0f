// Clip-space position of a shadow caster's vertex, chosen so that the
// rasterizer's own depth is what the map stores (or linearizes once), and
// no caster fragment has to write gl_FragDepth: a shader that writes depth
// turns off early depth testing and hierarchical Z for every fragment.
// ShadowMapPass draws with clip control GL_ZERO_TO_ONE, so window depth is
// clip z / clip w.
//
// Orthographic views (cascades): clip z = z-bar with w = 1. z-bar is affine
// in world space, and so in screen space, so interpolating it is exact,
// and its clip range [0, 1] is the view's [z0, z1].
// Perspective views (spot, cube faces): clip z = z_near with w = z, the
// depth along the axis: the stored depth is z_near / z, a reversed-Z
// projection with its far plane at infinity (1 at the near plane, falling
// towards 0), which keeps float32's relative precision at every distance
// (Reed, "Depth Precision Visualized", 2015; Lapidous and Jiao, 1999).
// Clipping keeps z >= z_near; what lies beyond z1 is stored beyond it and
// reads as 1 once linearized (the clear value it had when clipped). Spot
// views are linearized to z-bar after drawing (ShadowMapPass); a cube
// face's fragments still write their radial z-bar, which is not a
// projective function of the screen position.
#pragma once

// The axial depth below which a perspective view holds no caster. A spot
// view's z0 is an axial depth: z0 itself. A cube face's z0 is a distance
// from the light, and a caster at distance z0 towards a corner of the face
// (half-width t, guard band included) lies at axial depth z0 / sqrt(1 +
// 2 t^2): clipping at z0 would cut away every caster nearer the face's
// edges than its axis (a high slab beside the light loses its shadow). The
// same bound as the face's near plane (fit_cube_views).
float caster_near_depth(GpuShadowView view) {
  if (view.radial_depth == 0) return view.depth_range.x;
  // depth_range.z: the width of a texel at unit depth, 2 t / map size.
  float t = 0.5 * view.depth_range.z * view.depth_range.w;
  return 0.99 * view.depth_range.x / sqrt(1.0 + 2.0 * t * t);
}

vec4 caster_clip_position(GpuShadowView view, vec4 world) {
  vec4 clip = view.view_projection * world;
  float axial = -(view.view * world).z;
  if (view.perspective != 0) return vec4(clip.xy, caster_near_depth(view), axial);
  return vec4(clip.xy, (axial - view.depth_range.x) / (view.depth_range.y - view.depth_range.x),
              1.0);
}
