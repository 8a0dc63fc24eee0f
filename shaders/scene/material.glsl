// Scene materials (see src/render/gpu_scene.cpp: GpuMaterial).
struct Material {
  vec4 albedo;              // rgb: linear albedo
  vec4 specular_shininess;  // rgb: specular colour, w: Blinn-Phong exponent
};

layout(std430, binding = BINDING_MATERIALS_SSBO) readonly buffer MaterialsBlock {
  Material materials[];
};
