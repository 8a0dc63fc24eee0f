// Test kernel: sat_rectangle_average() (shaders/filter/sat.glsl) at a
// buffer of sub-texel rectangles, so that tests/gpu/filter_test.cpp can
// compare it with a double-precision integral of the map.
#include "../shared/bindings.h"
#include "../filter/sat.glsl"

layout(local_size_x = 64) in;

layout(binding = UNIT_COMPUTE_INPUT) uniform usampler2DArray table;

// xy: the centre, zw: the half-widths, in texels.
layout(std430, binding = 0) readonly buffer Rectangles { vec4 rectangles[]; };
layout(std430, binding = 1) writeonly buffer Averages { vec4 averages[]; };

layout(location = 0) uniform uint count;
layout(location = 1) uniform float scale;
layout(location = 2) uniform int layer;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  vec4 r = rectangles[i];
  averages[i] = sat_rectangle_average(table, layer, r.xy, r.zw, scale);
}
