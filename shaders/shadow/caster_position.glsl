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
// Perspective views (spot, cube faces): clip z = z0 with w = z, the depth
// along the axis: the stored depth is z0 / z, a reversed-Z projection with
// its far plane at infinity (1 at the near plane, falling towards 0), which
// keeps float32's relative precision at every distance (Reed, "Depth
// Precision Visualized", 2015; Lapidous and Jiao, 1999). Clipping keeps
// z >= z0, as the near plane did; what lies beyond z1 is stored beyond it
// and reads as 1 once linearized (the clear value it had when clipped).
// Spot views are linearized to z-bar after drawing (ShadowMapPass); a cube
// face's fragments still write their radial z-bar, which is not a
// projective function of the screen position.
#pragma once

vec4 caster_clip_position(GpuShadowView view, vec4 world) {
  vec4 clip = view.view_projection * world;
  float axial = -(view.view * world).z;
  if (view.perspective != 0) return vec4(clip.xy, view.depth_range.x, axial);
  return vec4(clip.xy, (axial - view.depth_range.x) / (view.depth_range.y - view.depth_range.x),
              1.0);
}
