// Shadow pass: the scene seen from one light.
#include "../common/uniforms.glsl"
#include "../scene/vertex_input.glsl"

layout(location = 0) uniform int u_light;

out float v_light_depth;  // linear light-space depth

void main() {
  GpuLight light = lights[u_light];
  vec4 world = vec4(in_position, 1.0);
  v_light_depth = -(light.view * world).z;
  gl_Position = light.view_projection * world;
}
