// Penumbra geometry of an area light (Fernando, "Percentage-Closer Soft
// Shadows", SIGGRAPH 2005 sketch): similar triangles between the light's
// source, the blocker and the receiver. Depths are linear light-space
// depths; view.source_width is the source's width (see GpuShadowView).
#pragma once

float linear_depth_of(GpuShadowView view, float z_bar) {
  return view.depth_range.x + z_bar * (view.depth_range.y - view.depth_range.x);
}

// World width of the penumbra on a receiver at depth d_receiver cast by a
// blocker at depth d_blocker: w_penumbra = (d_r - d_b) w_light / d_b
// (Fernando 2005, eq. 1); for a directional light, whose source width is
// given per unit of distance, (d_r - d_b) w_light.
float penumbra_world_width(GpuShadowView view, float d_receiver, float d_blocker) {
  float gap = max(d_receiver - d_blocker, 0.0);
  return view.perspective != 0 ? gap * view.source_width / max(d_blocker, 1e-6)
                               : gap * view.source_width;
}

// Width, in texels, of the cone from a receiver at depth d_receiver to the
// light's source where it crosses depth d: the map region where blockers
// at depth d can appear.
float cone_width_at(GpuShadowView view, float d_receiver, float d) {
  float world = view.source_width * max(d_receiver - d, 0.0);
  if (view.perspective != 0) return world / max(d_receiver, 1e-6) / (d * view.depth_range.z);
  return world / view.depth_range.z;
}

// Width, in texels, of the map region where blockers of the receiver can
// appear: the cone from the receiver to the light's source, widest at the
// nearest geometry z0 (Fernando's search over the light's extent on the
// near plane).
float blocker_search_width(GpuShadowView view, float d_receiver) {
  return cone_width_at(view, d_receiver, view.depth_range.x);
}
