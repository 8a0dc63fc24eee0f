// G-buffer pass: the scene from the camera.
#include "../common/uniforms.glsl"
#include "vertex_input.glsl"

out vec3 v_normal;
flat out uint v_material;

void main() {
  v_normal = in_normal;
  v_material = in_material;
  gl_Position = frame.projection * frame.view * vec4(in_position, 1.0);
}
