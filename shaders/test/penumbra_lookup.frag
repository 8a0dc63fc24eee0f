// The shadow lookup an engine includes (shadow/penumbra_shadows.glsl),
// called so that the block's members are active: the layout test
// (tests/gpu/uniform_layout_test.cpp) compares their offsets with
// ShadowBlock's.
#include "../shadow/penumbra_shadows.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  vec3 p = vec3(gl_FragCoord.xy, 0.0);
  out_color = vec4(penumbra_shadow(int(p.x) % 4, p, vec3(0.0, 1.0, 0.0)));
}
