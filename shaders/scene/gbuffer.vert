// G-buffer pass: the scene from the camera.
#include "../common/uniforms.glsl"
#include "material.glsl"
#include "vertex_input.glsl"

out vec3 v_normal;
out vec3 v_world;
out vec2 v_texcoord;  // in the base-colour texture
out vec4 v_color;
flat out uint v_material;

void main() {
  v_normal = in_normal;
  v_world = in_position;
  v_texcoord = texture_coordinate(materials[in_material], in_uv);
  v_color = in_color;
  v_material = in_material;
  gl_Position = frame.projection * frame.view * vec4(in_position, 1.0);
}
