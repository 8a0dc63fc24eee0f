// The Accumulator's two steps (src/render/accumulator.hpp), chosen by
// ACCUMULATE_STEP:
// - ADD: sum += the sub-frame's view, every channel (one read and one
//   read-modify-write of RGBA32F per pixel);
// - RESOLVE: the mean of the sums, or, for the weighted shadow view (whose
//   sub-frames hold lit, lit * w, w), the ratio sum(lit w) / sum(w), the
//   plain mean where no sub-frame's point reached the pixel (w = 0 for all:
//   a grazing receiver that sees a sliver of the source the N points
//   missed).
#include "../shared/bindings.h"

#define ACCUMULATE_ADD 0
#define ACCUMULATE_RESOLVE 1

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2D source;
#if ACCUMULATE_STEP == ACCUMULATE_ADD
layout(rgba32f, binding = IMAGE_OUTPUT) uniform image2D sum;
#else
layout(rgba32f, binding = IMAGE_OUTPUT) uniform writeonly image2D resolved;
layout(location = 0) uniform int count;
layout(location = 1) uniform int weighted;
#endif

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, textureSize(source, 0)))) return;
  vec4 value = texelFetch(source, p, 0);
#if ACCUMULATE_STEP == ACCUMULATE_ADD
  imageStore(sum, p, imageLoad(sum, p) + value);
#else
  vec4 mean = value / float(count);
  if (weighted != 0) {
    float lit = value.b > 0.0 ? value.g / value.b : mean.r;
    mean = vec4(vec3(lit), mean.a);
  }
  imageStore(resolved, p, mean);
#endif
}
