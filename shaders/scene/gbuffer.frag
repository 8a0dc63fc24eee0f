// Writes the surface attributes the lighting pass needs; position comes
// back from the depth buffer. CUT_OUTS (0 or 1): whether the surfaces drawn
// may have holes or backs to discard (a discard in the shader costs the
// opaque surfaces their early depth test, so they are drawn without).
#include "../shared/bindings.h"
#include "material.glsl"
#include "smooth_surface.glsl"
#include "surface.glsl"

in vec3 v_normal;
in vec3 v_world;
in vec2 v_texcoord;
in vec4 v_color;
flat in uint v_material;

layout(location = 0) out vec4 out_normal;    // xyz: world normal, w: shininess (0 = background)
layout(location = 1) out vec4 out_albedo;    // rgb: albedo (stored sRGB-encoded)
// rgb: specular colour, a: 1 on an opaque surface, 0 on a cut-out (its
// depth holds the mask's coverage at the pixel's centre only: the
// contact shadows' march takes no occluder from it)
layout(location = 2) out vec4 out_specular;
layout(location = 3) out vec4 out_facet;     // xyz: triangle normal, w: rise to the smooth surface

void main() {
  Material m = materials[v_material];
  vec4 base = base_color(m, v_texcoord, v_color);
#if CUT_OUTS
  if (is_discarded(m, base.a)) discard;
#endif
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;  // double-sided surfaces seen from behind
  out_normal = vec4(n, m.specular_shininess.w);
  out_albedo = vec4(base.rgb, 1.0);
  out_specular = vec4(m.specular_shininess.rgb, m.uv_row0.w < 0.0 ? 1.0 : 0.0);
  SmoothSurface surface = smooth_surface(v_world, n);
  out_facet = vec4(surface.facet_normal, surface.height);
}
