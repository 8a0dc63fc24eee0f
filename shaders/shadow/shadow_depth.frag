// The scene's casters in one shadow view. The map stores the relative
// depth z-bar = (z - z0) / (z1 - z0), where z is the depth along the
// view's axis (spot, directional) or the distance from the light (point
// lights: the same quantity on every face of the cube, so the shadow is
// continuous across faces): linear in light-space distance for every
// light, so every technique stores and compares the same quantity.
//
// Only a point light's radial depth is written here (RADIAL_DEPTH 1), and
// a spot light's virtual pages' z-bar (VIRTUAL_PAGE 1 with RADIAL_DEPTH 1:
// the view is the page's level, virtual_page.vert); for
// the other views the rasterizer's depth is z-bar itself (orthographic) or
// is linearized to it once per texel after drawing (perspective: see
// caster_position.glsl), so these fragments write no depth and keep their
// early depth test and hierarchical Z. Along any ray from the light every
// order agrees, so the depth test keeps the nearest surface.
//
// Alpha-tested casters (leaf cards, fences) leave their holes out, in
// every view (spot, cube face, cascade) and so for every technique, whose
// representations are all resolved from this depth; single-sided surfaces
// cast only from their front. CUT_OUTS (0 or 1): whether the surfaces
// drawn may be discarded. A shader that may discard keeps an early depth
// test but defers its depth write past the discard; opaque surfaces are
// drawn without it, so their fragments are culled and written early.
#include "../common/uniforms.glsl"
#include "../scene/material.glsl"
#include "../scene/surface.glsl"
#include "lookup.glsl"

#ifndef RADIAL_DEPTH
#define RADIAL_DEPTH 0
#endif
#ifndef VIRTUAL_PAGE
#define VIRTUAL_PAGE 0
#endif
// SECOND_SURFACES 1: a view's second surfaces (ShadowMapPass::execute()'s
// draw_second, for backprojection): only fragments behind the first
// layer's surface, by more than this gap of z-bar (the same surface's
// fragment lands within rounding of it), are kept.
#ifndef SECOND_SURFACES
#define SECOND_SURFACES 0
#endif
#if SECOND_SURFACES
const float SECOND_SURFACE_GAP = 1.0e-4;
layout(binding = UNIT_SHADOW_DEPTH) uniform sampler2DArray first_surfaces;
#endif
#if VIRTUAL_PAGE
#include "virtual_lookup.glsl"
flat in int v_level;
#endif

layout(location = 0) uniform int u_view;

in vec3 v_view_position;
in vec2 v_texcoord;
in float v_alpha;
flat in uint v_material;

void main() {
#if CUT_OUTS
  Material m = materials[v_material];
  if (is_discarded(m, base_color(m, v_texcoord, vec4(1.0, 1.0, 1.0, v_alpha)).a)) discard;
#endif
#if SECOND_SURFACES
  {
    GpuShadowView view = shadow_views[u_view];
    float z_bar = relative_depth_of(view, view_space_depth(view, v_view_position));
    float first = texelFetch(first_surfaces, ivec3(ivec2(gl_FragCoord.xy), u_view), 0).r;
    if (z_bar <= first + SECOND_SURFACE_GAP) discard;
  }
#endif
#if RADIAL_DEPTH
#if VIRTUAL_PAGE
  GpuShadowView view = virtual_shadow.levels[v_level];
#else
  GpuShadowView view = shadow_views[u_view];
#endif
  gl_FragDepth = clamp(relative_depth_of(view, view_space_depth(view, v_view_position)), 0.0, 1.0);
#endif
}
