// A surface's base colour and coverage in a fragment shader (the G-buffer
// and the shadow depth pass), from its material and base-colour texture.
// Needs material.glsl.
layout(binding = UNIT_BASE_COLOR) uniform sampler2D base_color_texture;

// The base colour (linear rgb, coverage in a) at an interpolated texture
// coordinate and vertex colour: the material's factor times the vertex
// colour times the texture (src/scene/texture.hpp: sample_texture is the
// CPU's twin). Untextured materials are drawn with a white texel bound, so
// the texture is read in uniform control flow (implicit derivatives are
// undefined in non-uniform flow: GLSL 4.50, section 8.9).
vec4 base_color(Material m, vec2 texcoord, vec4 vertex_color) {
  return m.albedo * vertex_color * texture(base_color_texture, texcoord);
}

// Whether this fragment is not drawn: a hole of an alpha-tested surface
// (glTF MASK, and BLEND as MASK at 0.5), or the back of a single-sided one.
bool is_discarded(Material m, float coverage) {
  if (!gl_FrontFacing && !material_has(m, MATERIAL_DOUBLE_SIDED)) return true;
  return coverage < m.uv_row0.w;
}
