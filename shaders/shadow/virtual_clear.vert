// Virtual shadow maps: clears each listed pool page to the far depth
// before its casters are drawn: a full-screen triangle per page at depth 1
// (drawn with GL_ALWAYS), in the page's layer.
#extension GL_ARB_shader_viewport_layer_array : require
#include "../shared/bindings.h"

layout(std430, binding = BINDING_VIRTUAL_RENDER_LIST_SSBO) readonly buffer RenderList {
  ivec4 render_list[];
};
layout(location = 0) uniform int u_list_start;  // virtual_page.vert's

void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);
  gl_Layer = render_list[u_list_start + gl_InstanceID].w;
}
