// The bandwidth yardstick of `penumbra bench`: read every texel once and
// write it once, the least any filter pass over the map can do.
#include "../shared/bindings.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2D source;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly image2D target;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, textureSize(source, 0)))) return;
  imageStore(target, p, texelFetch(source, p, 0));
}
