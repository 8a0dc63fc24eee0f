// Scene materials (see src/render/gpu_scene.hpp: GpuMaterial).
struct Material {
  vec4 albedo;              // rgb: linear albedo, a: coverage factor
  vec4 specular_shininess;  // rgb: specular colour, w: Blinn-Phong exponent
  vec4 uv_row0;             // xyz: first row of the uv transform, w: coverage cutoff (< 0: opaque)
  vec4 uv_row1;             // xyz: second row, w: MATERIAL_* flags
};

layout(std430, binding = BINDING_MATERIALS_SSBO) readonly buffer MaterialsBlock {
  Material materials[];
};

bool material_has(Material m, int flag) {
  return (int(m.uv_row1.w) & flag) != 0;
}

// The texture coordinate of a vertex's uv (src/scene/texture.hpp:
// texture_coordinate). Computed per vertex and interpolated, so that the
// derivatives that pick the mip level come from varyings alone (helper
// invocations need not read the materials buffer).
vec2 texture_coordinate(Material m, vec2 uv) {
  return vec2(dot(m.uv_row0.xyz, vec3(uv, 1.0)), dot(m.uv_row1.xyz, vec3(uv, 1.0)));
}
