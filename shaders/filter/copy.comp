// The bandwidth yardstick of `penumbra bench`: read every texel once and
// write it once, the least any filter pass over the map can do. One
// workgroup layer per array layer.
#include "../shared/bindings.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray source;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly image2DArray target;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p.xy, textureSize(source, 0).xy))) return;
  imageStore(target, p, texelFetch(source, p, 0));
}
