// A surface's base colour and coverage in a fragment shader (the G-buffer
// and the shadow depth pass), from its material and base-colour texture.
// Needs material.glsl.
layout(binding = UNIT_BASE_COLOR) uniform sampler2D base_color_texture;
layout(binding = UNIT_BASE_ALPHA) uniform sampler2D base_alpha_texture;

// The base colour (linear rgb, coverage in a) at an interpolated texture
// coordinate and vertex colour: the material's factor times the vertex
// colour times the texture (src/scene/texture.hpp: sample_texture is the
// CPU's twin). Untextured materials are drawn with a white texel bound, so
// the texture is read in uniform control flow (implicit derivatives are
// undefined in non-uniform flow: GLSL 4.50, section 8.9).
//
// The alpha is read through a sampler of its own (UNIT_BASE_ALPHA: the
// same texture, bilinear in the level nearest to the footprint's, not
// anisotropic). Trilinear and anisotropic filtering average two levels, or
// several points, of an alpha-tested texture's chain, pulling its alpha
// towards the mean and under the cutoff: leaves would thin out again. Each
// level of that chain keeps level 0's coverage as a bilinear filter reads
// it (src/scene/coverage_mips.hpp), so the test keeps it at every distance
// and shadow-map size.
vec4 base_color(Material m, vec2 texcoord, vec4 vertex_color) {
  vec4 texel = texture(base_color_texture, texcoord);
  texel.a = texture(base_alpha_texture, texcoord).a;
  return m.albedo * vertex_color * texel;
}

// Whether this fragment is not drawn: a hole of an alpha-tested surface
// (glTF MASK, and BLEND as MASK at 0.5), or the back of a single-sided one.
bool is_discarded(Material m, float coverage) {
  if (!gl_FrontFacing && !material_has(m, MATERIAL_DOUBLE_SIDED)) return true;
  return coverage < m.uv_row0.w;
}
