// Scene materials (see src/render/gpu_scene.hpp: GpuMaterial) and their
// base-colour texture.
struct Material {
  vec4 albedo;              // rgb: linear albedo, a: coverage factor
  vec4 specular_shininess;  // rgb: specular colour, w: Blinn-Phong exponent
  vec4 uv_row0;             // xyz: first row of the uv transform, w: coverage cutoff (< 0: opaque)
  vec4 uv_row1;             // xyz: second row, w: MATERIAL_* flags
};

layout(std430, binding = BINDING_MATERIALS_SSBO) readonly buffer MaterialsBlock {
  Material materials[];
};

layout(binding = UNIT_BASE_COLOR) uniform sampler2D base_color_texture;

bool material_has(Material m, int flag) {
  return (int(m.uv_row1.w) & flag) != 0;
}

// The base colour (linear rgb, coverage in a) at a vertex-interpolated uv
// and colour: the material's factor times the vertex colour times the
// texture (src/scene/texture.hpp: sample_texture is the CPU's twin).
vec4 base_color(Material m, vec2 uv, vec4 vertex_color) {
  vec4 c = m.albedo * vertex_color;
  if (material_has(m, MATERIAL_TEXTURED)) {
    vec2 t = vec2(dot(m.uv_row0.xyz, vec3(uv, 1.0)), dot(m.uv_row1.xyz, vec3(uv, 1.0)));
    c *= texture(base_color_texture, t);
  }
  return c;
}

// Whether this fragment is not drawn: a hole of an alpha-tested surface
// (glTF MASK, and BLEND as MASK at 0.5), or the back of a single-sided one.
bool is_discarded(Material m, float coverage) {
  if (!gl_FrontFacing && !material_has(m, MATERIAL_DOUBLE_SIDED)) return true;
  return coverage < m.uv_row0.w;
}
