// Lays layers [first, first + count) of a 2D array side by side in one 2D
// texture, `columns` to a row, the first at the top left (image rows run
// top to bottom, GL rows bottom to top), for the map views of a light with
// several shadow views (a point light's cube faces, the cascades). Tiles
// past the last layer are black. IMAGE_FORMAT: the output's (r32f for depth
// maps, or the representation's channels in floats).
#include "../shared/bindings.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray layers;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly image2D tiled;
layout(location = 0) uniform int u_first;
layout(location = 1) uniform int u_count;
layout(location = 2) uniform int u_columns;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 out_size = imageSize(tiled);
  if (any(greaterThanEqual(p, out_size))) return;
  ivec2 size = textureSize(layers, 0).xy;
  int rows = out_size.y / size.y;
  ivec2 tile = p / size;
  int k = (rows - 1 - tile.y) * u_columns + tile.x;
  vec4 value = k < u_count ? texelFetch(layers, ivec3(p - tile * size, u_first + k), 0) : vec4(0.0);
  imageStore(tiled, p, value);
}
