// Writes the (2 RADIUS + 1)^2 box average of every texel, read from a
// summed-area table: the "moments-filtered" view of a SAT-filtered map, and
// the GPU side of the SAT tests.
#include "../shared/bindings.h"
#include "sat.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = UNIT_COMPUTE_INPUT) uniform usampler2DArray table;
layout(rgba32f, binding = IMAGE_OUTPUT) uniform writeonly image2DArray averages;
layout(location = 0) uniform int u_radius;
layout(location = 1) uniform float u_scale;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p.xy, textureSize(table, 0).xy))) return;
  // The texel-centred rectangle of half-width RADIUS + 1/2 is the box.
  imageStore(averages, p,
             sat_rectangle_average(table, p.z, vec2(p.xy) + 0.5, vec2(float(u_radius) + 0.5),
                                   u_scale));
}
