// Writes relative depth z-bar = (z - z0) / (z1 - z0), where z is the depth
// along the view's axis (spot, directional) or the distance from the light
// (point lights: the same quantity on every face of the cube, so the
// shadow is continuous across faces). Linear in light-space distance for
// every light, so every technique stores and compares the same quantity
// (the hardware depth of a perspective projection would be non-linear).
// Along any ray from the light both orders agree, so the depth test keeps
// the nearest surface either way.
//
// Alpha-tested casters (leaf cards, fences) leave their holes out before
// depth is written, in every view (spot, cube face, cascade) and so for
// every technique, whose representations are all resolved from this
// depth; single-sided surfaces cast only from their front. CUT_OUTS (0 or
// 1): whether the surfaces drawn may be discarded (opaque ones are drawn
// without, keeping their early depth test).
#include "../common/uniforms.glsl"
#include "../scene/material.glsl"
#include "../scene/surface.glsl"
#include "lookup.glsl"

layout(location = 0) uniform int u_view;

in vec3 v_view_position;
in vec2 v_texcoord;
in float v_alpha;
flat in uint v_material;
layout(depth_any) out float gl_FragDepth;

void main() {
#if CUT_OUTS
  Material m = materials[v_material];
  if (is_discarded(m, base_color(m, v_texcoord, vec4(1.0, 1.0, 1.0, v_alpha)).a)) discard;
#endif
  GpuShadowView view = shadow_views[u_view];
  gl_FragDepth = clamp(relative_depth_of(view, view_space_depth(view, v_view_position)), 0.0, 1.0);
}
