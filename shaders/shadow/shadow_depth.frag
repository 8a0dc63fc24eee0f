// Writes relative depth z-bar = (z - z0) / (z1 - z0), linear in light-space
// depth for spot and directional lights alike, so every technique stores
// and compares the same quantity (the hardware depth of a perspective
// projection would be non-linear).
#include "../common/uniforms.glsl"

layout(location = 0) uniform int u_light;

in float v_light_depth;
layout(depth_any) out float gl_FragDepth;

void main() {
  vec4 range = lights[u_light].depth_range;
  gl_FragDepth = clamp((v_light_depth - range.x) / (range.y - range.x), 0.0, 1.0);
}
