// World-space scene vertices (see src/scene/mesh.hpp: Vertex).
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in uint in_material;
layout(location = 3) in vec2 in_uv;
layout(location = 4) in vec4 in_color;  // linear RGBA, from 8-bit unorm
